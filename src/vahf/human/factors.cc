#include "vahf/human/factors.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "vahf/core/error.h"

namespace vahf::human {

double Visibility(std::int64_t visible_pixels, std::int64_t part_pixels) {
  VAHF_CHECK(visible_pixels >= 0 && visible_pixels <= part_pixels,
             "Eq. 1 needs 0 <= V_a <= V_b");
  if (part_pixels == 0) return 0.0;
  return static_cast<double>(visible_pixels) / static_cast<double>(part_pixels);
}

double VisionCoefficient(double V, double f) { return 1.0 - V * f; }

double ComfortCoefficient(double r, double g, double V) {
  return 1.0 - 0.5 * (r + g) * V;
}

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  VAHF_CHECK(a.norm() > 0 && b.norm() > 0, "angle of a zero vector");
  // atan2 of |a x b| and a.b is accurate near 0 and 180 degrees, unlike acos.
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

// A part centred on the eye itself has no sight line: the operator looks
// straight at it, angle 0 (a scene may place a part anywhere in the workcell).
double SightAngleDeg(const Posture& posture, const Eigen::Vector3d& part_centre,
                     const Eigen::Vector3d& motion_direction) {
  const Eigen::Vector3d sight = part_centre - posture.eye;
  return sight.norm() > 0 ? AngleDeg(sight, motion_direction) : 0.0;
}

double GlanceAngleDeg(const Posture& posture, const Eigen::Vector3d& part_centre) {
  const Eigen::Vector3d sight = part_centre - posture.eye;
  return sight.norm() > 0 ? AngleDeg(sight, posture.down) : 0.0;
}

double ShoulderDistance(const Posture& posture, const Eigen::Vector3d& part_centre) {
  return std::max((posture.left_shoulder - part_centre).norm(),
                  (posture.right_shoulder - part_centre).norm());
}

FactorValues EvaluateFactors(const FactorCurves& curves, const Posture& posture,
                             const Eigen::Vector3d& part_centre,
                             const Eigen::Vector3d& motion_direction, double V) {
  FactorValues out;
  out.V = V;
  out.sight_angle_deg = SightAngleDeg(posture, part_centre, motion_direction);
  out.f = curves.sight(out.sight_angle_deg);
  out.eta = VisionCoefficient(V, out.f);
  out.shoulder_distance = ShoulderDistance(posture, part_centre);
  out.r = curves.reach(out.shoulder_distance);
  out.glance_angle_deg = GlanceAngleDeg(posture, part_centre);
  out.g = curves.glance(out.glance_angle_deg);
  out.lambda_c = ComfortCoefficient(out.r, out.g, V);
  return out;
}

}  // namespace vahf::human
