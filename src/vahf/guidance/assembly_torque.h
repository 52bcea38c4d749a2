// The assembly torque (docs/design.md decision 3): the operator turns the part
// toward a held target orientation, drawn at each decision as the target
// orientation perturbed by a random rotation scaled by eta (like E_i of Eq. 5).
#pragma once

#include <Eigen/Core>

#include "vahf/guidance/assembly_force.h"
#include "vahf/rng/stream.h"

namespace vahf::guidance {

// The held orientation: target * exp(eta * sigma * n), n three standard
// normals from Purpose::kTorqueError at this decision.
Eigen::Matrix3d DrawHeldOrientation(const GuidanceParams& params, rng::StreamKey key,
                                    std::uint64_t decision, const Eigen::Matrix3d& target,
                                    double eta);

// tau = I (Psi w^2 theta - 2 zeta w omega), theta the rotation vector (world)
// from the current orientation R to the held one, I the inertia about the
// centre of mass in the world frame (kg m^2), omega the angular velocity (world).
Eigen::Vector3d AssemblyTorque(const GuidanceParams& params, double psi,
                               const Eigen::Matrix3d& inertia_world,
                               const Eigen::Matrix3d& rotation,
                               const Eigen::Matrix3d& held, const Eigen::Vector3d& omega);

}  // namespace vahf::guidance
