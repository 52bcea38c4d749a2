// The free body's Jacobian (rigid_body_jacobian.h) against central differences
// of Derivative, the function CVODE integrates, at a state whose quaternion is
// not of unit length (MotionOf normalises it, qdot does not): under constant
// loads (the Newton-Euler terms alone: turning inertia, gyroscopic term, the
// centre of mass off the origin), and under loads that depend on the whole
// motion (a spring-damper at a point of the body and a torque that follows
// its orientation), whose derivative is given by differences in the motion's
// columns, so that the chain rule to the state is tested on its own.
#include "vahf/sim/rigid_body_jacobian.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "support/motion_differences.h"
#include "vahf/scene/parameters.h"

namespace vahf::sim {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

const std::vector<int> kSegments = {3, 4, 3, 3};  // p, q, v, w

human::FactorCurves Curves() {
  const scene::Parameters p;  // the curves play no part here
  return {p.sight.Build(), p.reach.Build(0.74, 1.75), p.glance.Build()};
}

// 2 kg, inertia diag(0.01, 0.02, 0.03) about a centre 5 cm off the origin,
// with a product of inertia, turned about an oblique axis and spinning.
struct Body {
  TrialModel model{Curves()};
  BodyState y;
  Vector3d gravity{0, 0, -9.80665};
  Body() {
    model.mass = 2.0;
    model.com = Vector3d(0.05, -0.02, 0.03);
    model.inertia_body << 0.01, 0.001, 0, 0.001, 0.02, -0.002, 0, -0.002, 0.03;
    contact::RigidMotion m;
    m.pose.linear() =
        Eigen::AngleAxisd(0.6, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    m.pose.translation() = Vector3d(0.1, 0.2, 0.9);
    m.velocity = {0.3, -0.1, 0.2};
    m.angular_velocity = {1.5, -2.0, 0.7};
    y = StateOf(m);
    y.segment<4>(3) *= 1.2;  // CVODE's state drifts off the unit sphere between restarts
  }
};

// Loads at a motion: a spring-damper pulling the body point a towards x0,
// plus a torque turning the body's x axis towards the world's z.
Loads SpringLoads(const contact::RigidMotion& m) {
  const Vector3d a(0.02, 0.01, -0.03), x0(0.12, 0.18, 0.95);
  const Vector3d r = m.pose.linear() * a;
  Loads l;
  l.force = -300.0 * (m.pose.translation() + r - x0) -
            4.0 * (m.velocity + m.angular_velocity.cross(r));
  l.torque = r.cross(l.force) + 0.5 * m.pose.linear().col(0).cross(Vector3d::UnitZ()) -
             0.05 * m.angular_velocity;
  return l;
}

Eigen::VectorXd Stacked(const Loads& l) {
  Eigen::VectorXd out(6);
  out << l.force, l.torque;
  return out;
}

// d f / dy by central differences.
template <class F>
Eigen::MatrixXd StateDifferences(const F& f, const BodyState& y) {
  Eigen::MatrixXd out(kBodyStateSize, kBodyStateSize);
  for (int j = 0; j < kBodyStateSize; ++j) {
    const double h = 1e-7;
    BodyState up = y, down = y;
    up[j] += h;
    down[j] -= h;
    out.col(j) = (f(up) - f(down)) / (up[j] - down[j]);  // the step as represented
  }
  return out;
}

TEST(RigidBodyJacobian, ConstantLoads) {
  const Body b;
  Loads loads;
  loads.force = {1.0, -2.0, 0.5};
  loads.torque = {0.03, 0.01, -0.02};
  const BodyJacobian J =
      DerivativeJacobian(b.model, b.y, loads, LoadJacobian::Zero(), b.gravity);
  const Eigen::MatrixXd differences = StateDifferences(
      [&](const BodyState& y) { return Derivative(b.model, y, loads, b.gravity); }, b.y);
  EXPECT_TRUE(
      vahf::testing::BlocksAgree(J, differences, 1e-6, 1e-9, kSegments, kSegments));
  // Scaling the quaternion turns nothing: its radial direction is in the
  // null space of every row but qdot's.
  const Eigen::VectorXd radial = (Eigen::VectorXd(13) << Eigen::VectorXd::Zero(3),
                                  b.y.segment<4>(3), Eigen::VectorXd::Zero(6))
                                     .finished();
  EXPECT_LT((J * radial).tail<6>().norm(), 1e-12 * J.norm());
}

TEST(RigidBodyJacobian, MotionDependentLoads) {
  const Body b;
  const contact::RigidMotion m = MotionOf(b.y);
  const LoadJacobian dloads = vahf::testing::MotionDifferences(
      [](const contact::RigidMotion& x) { return Stacked(SpringLoads(x)); }, m,
      {1e-7, 1e-7, 1e-7, 1e-7});
  const BodyJacobian J =
      DerivativeJacobian(b.model, b.y, SpringLoads(m), dloads, b.gravity);
  const Eigen::MatrixXd differences = StateDifferences(
      [&](const BodyState& y) {
        return Derivative(b.model, y, SpringLoads(MotionOf(y)), b.gravity);
      },
      b.y);
  EXPECT_TRUE(
      vahf::testing::BlocksAgree(J, differences, 1e-6, 1e-9, kSegments, kSegments));
}

}  // namespace
}  // namespace vahf::sim
