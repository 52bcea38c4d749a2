#include "vahf/guidance/assembly_torque.h"

#include <Eigen/Geometry>
#include <cmath>

namespace vahf::guidance {

Eigen::Matrix3d DrawHeldOrientation(const GuidanceParams& params, rng::StreamKey key,
                                    std::uint64_t decision, const Eigen::Matrix3d& target,
                                    double eta) {
  rng::Stream s(key, decision, rng::Purpose::kTorqueError);
  const double n1 = s.Normal();
  const double n2 = s.Normal();
  const double n3 = s.Normal();
  const Eigen::Vector3d v =
      eta * params.torque_sigma_deg * (M_PI / 180.0) * Eigen::Vector3d(n1, n2, n3);
  const double angle = v.norm();
  if (!(angle > 0)) return target;
  return target * Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

Eigen::Vector3d AssemblyTorque(const GuidanceParams& params, double psi,
                               const Eigen::Matrix3d& inertia_world,
                               const Eigen::Matrix3d& rotation,
                               const Eigen::Matrix3d& held,
                               const Eigen::Vector3d& omega) {
  const Eigen::AngleAxisd error(held * rotation.transpose());  // world frame
  const Eigen::Vector3d theta = error.angle() * error.axis();
  const double w = params.torque_frequency;
  return inertia_world *
         (psi * w * w * theta - 2.0 * params.torque_damping_ratio * w * omega);
}

}  // namespace vahf::guidance
