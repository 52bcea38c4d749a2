#include "vahf/human/operator_model.h"

#include <Eigen/Geometry>
#include <cmath>

#include "vahf/core/error.h"

namespace vahf::human {

void BodyPlaneFrom(const Eigen::Vector3d& left_shoulder,
                   const Eigen::Vector3d& right_shoulder,
                   const Eigen::Vector3d& body_centre, const Eigen::Vector3d& facing,
                   Eigen::Vector3d* forward, Eigen::Vector3d* down) {
  const Eigen::Vector3d mid = 0.5 * (left_shoulder + right_shoulder);
  const Eigen::Vector3d across = right_shoulder - left_shoulder;
  Eigen::Vector3d d = body_centre - mid;
  Eigen::Vector3d n = across.cross(d);
  VAHF_CHECK(n.norm() > 1e-12 * across.norm() * d.norm() && across.norm() > 0,
             "body landmarks are collinear");
  n.normalize();
  if (n.dot(facing) < 0) n = -n;
  // Down is the in-plane direction perpendicular to the shoulder line.
  d -= d.dot(across) / across.squaredNorm() * across;
  *forward = n;
  *down = d.normalized();
}

Posture StandingPosture(const Operator& op) {
  const Anthropometry& a = op.proportions;
  const double h = op.height;
  const double yaw = op.facing_deg * M_PI / 180.0;
  const Eigen::Vector3d facing(std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(facing);  // operator's left
  const Eigen::Vector3d base(op.position.x(), op.position.y(), 0.0);

  Posture p;
  p.left_shoulder = base + a.shoulder_height * h * Eigen::Vector3d::UnitZ() +
                    0.5 * a.shoulder_width * h * left;
  p.right_shoulder = base + a.shoulder_height * h * Eigen::Vector3d::UnitZ() -
                     0.5 * a.shoulder_width * h * left;
  p.body_centre =
      base + 0.5 * (a.shoulder_height + a.hip_height) * h * Eigen::Vector3d::UnitZ();
  p.eye = base + a.eye_height * h * Eigen::Vector3d::UnitZ() + a.eye_forward * h * facing;
  BodyPlaneFrom(p.left_shoulder, p.right_shoulder, p.body_centre, facing, &p.forward,
                &p.down);
  return p;
}

}  // namespace vahf::human
