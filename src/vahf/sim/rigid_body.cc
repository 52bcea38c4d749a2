#include "vahf/sim/rigid_body.h"

#include <Eigen/Geometry>

namespace vahf::sim {

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

BodyState StateOf(const contact::RigidMotion& m) {
  Quaterniond q(m.pose.linear());
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  BodyState y;
  y << m.pose.translation(), q.w(), q.x(), q.y(), q.z(), m.velocity, m.angular_velocity;
  return y;
}

contact::RigidMotion MotionOf(const BodyState& y) {
  contact::RigidMotion m;
  const Quaterniond q = Quaterniond(y[3], y[4], y[5], y[6]).normalized();
  m.pose.linear() = q.toRotationMatrix();
  m.pose.translation() = y.segment<3>(0);
  m.velocity = y.segment<3>(7);
  m.angular_velocity = y.segment<3>(10);
  return m;
}

void NormaliseQuaternion(BodyState* y) { y->segment<4>(3).normalize(); }

BodyState Derivative(const TrialModel& model, const BodyState& y, const Loads& loads,
                     const Vector3d& gravity) {
  const Quaterniond q = Quaterniond(y[3], y[4], y[5], y[6]).normalized();
  const Matrix3d R = q.toRotationMatrix();
  const Vector3d v = y.segment<3>(7), w = y.segment<3>(10);
  const Vector3d c = R * model.com;  // origin to centre of mass, world
  const Matrix3d I = R * model.inertia_body * R.transpose();
  const Vector3d tau_c = loads.torque - c.cross(loads.force);
  const Vector3d alpha = I.ldlt().solve(tau_c - w.cross(I * w));
  const Vector3d a =
      loads.force / model.mass + gravity - alpha.cross(c) - w.cross(w.cross(c));
  // qdot = 1/2 [0, w] (x) q for a world-frame w.
  const Quaterniond raw(y[3], y[4], y[5], y[6]);
  const Quaterniond qdot = Quaterniond(0, w.x(), w.y(), w.z()) * raw;
  BodyState dy;
  dy << v, 0.5 * qdot.w(), 0.5 * qdot.x(), 0.5 * qdot.y(), 0.5 * qdot.z(), a, alpha;
  return dy;
}

}  // namespace vahf::sim
