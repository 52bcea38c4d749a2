// Derivatives of the operator's force and torque (assembly_force.h,
// assembly_torque.h) with respect to what they read of the part's state, for
// implicit integrators: the chain rule through the same formulas, exact
// wherever they are differentiable (at a kink, ContactBlend's clamps or
// |P (T' - T)| = 0, one side's).
#pragma once

#include <Eigen/Core>

#include "vahf/guidance/assembly_force.h"

namespace vahf::guidance {

// d ContactBlend / d normal_force: the smoothstep's 6 s (1 - s) / blend_force
// inside the clamps, 0 outside.
double ContactBlendSlope(double normal_force, double blend_force);

// Partials of ImpedanceForce: w.r.t. the position T, the velocity v, the
// contact's normal force vector F_n and its friction f.
struct ImpedancePartials {
  Eigen::Matrix3d position = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d velocity = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d normal_force = Eigen::Matrix3d::Zero();
  Eigen::Vector3d friction = Eigen::Vector3d::Zero();
};

// The partials of ImpedanceForce at the same arguments.
ImpedancePartials ImpedanceForceJacobian(const GuidanceParams& params, double psi,
                                         double mass, const Eigen::Vector3d& position,
                                         const Eigen::Vector3d& estimated_target,
                                         const Eigen::Vector3d& velocity,
                                         const FeltContact& contact, double blend_force,
                                         const Eigen::Vector3d& weight,
                                         double fade_length);

// The partials of WithdrawalForce at the same arguments (normal_force zero:
// the pull does not read the contact's normal).
ImpedancePartials WithdrawalForceJacobian(const GuidanceParams& params, double psi,
                                          double mass, const Eigen::Vector3d& position,
                                          const Eigen::Vector3d& withdrawal_target,
                                          double friction, double fade_length);

// Partials of AssemblyTorque: w.r.t. a small world rotation dtheta of the part
// (rotation -> exp([dtheta]x) rotation, inertia_world turning with it:
// inertia_world = rotation I rotation^T) and w.r.t. omega.
struct TorquePartials {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d omega = Eigen::Matrix3d::Zero();
};

TorquePartials AssemblyTorqueJacobian(const GuidanceParams& params, double psi,
                                      const Eigen::Matrix3d& inertia_world,
                                      const Eigen::Matrix3d& rotation,
                                      const Eigen::Matrix3d& held,
                                      const Eigen::Vector3d& omega);

// The inverse right Jacobian of SO(3) at the rotation vector theta:
// log(exp(theta) exp(phi)) = theta + InverseRightJacobian(theta) phi + O(phi^2),
//   J_r^-1 = I + [theta]x / 2 + (1 / t^2 - (1 + cos t) / (2 t sin t)) [theta]x^2,
// t = |theta| < pi (J. Sola, J. Deray, D. Atchuthan, "A micro Lie theory for
// state estimation in robotics", arXiv:1812.01537, 2018, Eq. 144).
Eigen::Matrix3d InverseRightJacobian(const Eigen::Vector3d& theta);

}  // namespace vahf::guidance
