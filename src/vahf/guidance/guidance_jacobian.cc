#include "vahf/guidance/guidance_jacobian.h"

#include <Eigen/Geometry>
#include <cmath>

#include "vahf/core/cross_matrix.h"

namespace vahf::guidance {

using Eigen::Matrix3d;
using Eigen::Vector3d;

double ContactBlendSlope(double normal_force, double blend_force) {
  const double s = normal_force / blend_force;
  if (!(s > 0 && s < 1)) return 0.0;
  return 6.0 * s * (1.0 - s) / blend_force;
}

// ImpedanceForce (assembly_force.cc) term by term, with d = T' - T, n = F_n / |F_n|,
// a = P d = d - (d . n) n, g = sqrt(|a|^2 + e^2):
//   F = kappa Psi d - (1 - w) s W - w kappa Psi (d . n) n + w f a / g - b v
// and dn = (I - n n^T) dF_n / |F_n|, dw = w' n^T dF_n,
// da = P dd - ((d . n) I + n d^T) dn, d(a / g) = (I / g - a a^T / g^3) da.
ImpedancePartials ImpedanceForceJacobian(const GuidanceParams& params, double psi,
                                         double mass, const Vector3d& position,
                                         const Vector3d& estimated_target,
                                         const Vector3d&, const FeltContact& contact,
                                         double blend_force, const Vector3d& weight,
                                         double fade_length) {
  const Matrix3d I = Matrix3d::Identity();
  const double kp = params.kappa * psi;
  ImpedancePartials out;
  out.position = -kp * I;
  out.velocity = -ForceDamping(params, psi, mass) * I;
  const double fn = contact.normal_force.norm();
  const double w = ContactBlend(fn, blend_force);
  if (!(w > 0)) return out;  // fn = 0: w and its slope vanish
  const Vector3d d = estimated_target - position;
  const Vector3d n = contact.normal_force / fn;
  const Matrix3d P = I - n * n.transpose();
  const double dn_ = d.dot(n);
  const Vector3d a = d - dn_ * n;
  const double g = std::sqrt(a.squaredNorm() + fade_length * fade_length);
  const Matrix3d da_unit = I / g - a * a.transpose() / (g * g * g);  // d(a / g) / da
  const Matrix3d dn_dF = P / fn;
  const Eigen::RowVector3d dw_dF = ContactBlendSlope(fn, blend_force) * n.transpose();
  const Matrix3d da_dF = -(dn_ * I + n * d.transpose()) * dn_dF;
  const double push = FrictionPush(contact.friction, params.max_push);
  // Position: dd = -dT.
  out.position += w * kp * n * n.transpose() - w * push * da_unit * P;
  // Normal force: through w, n and a.
  out.normal_force =
      params.weight_support * weight * dw_dF -
      kp * (dn_ * n * dw_dF + w * dn_ * dn_dF + w * n * d.transpose() * dn_dF) +
      push * (a / g) * dw_dF + w * push * da_unit * da_dF;
  out.friction = w * FrictionPushSlope(contact.friction, params.max_push) * a / g;
  return out;
}

ImpedancePartials WithdrawalForceJacobian(const GuidanceParams& params, double psi,
                                          double mass, const Vector3d& position,
                                          const Vector3d& withdrawal_target,
                                          double friction, double fade_length) {
  const Matrix3d I = Matrix3d::Identity();
  const double kp = params.kappa * psi;
  const Vector3d d = withdrawal_target - position;
  const double g = std::sqrt(d.squaredNorm() + fade_length * fade_length);
  const double push = FrictionPush(friction, params.max_push);
  ImpedancePartials out;
  // dd = -dT; d(d / g) / dd = I / g - d d^T / g^3.
  out.position = -kp * I - push * (I / g - d * d.transpose() / (g * g * g));
  out.velocity = -ForceDamping(params, psi, mass) * I;
  out.friction = FrictionPushSlope(friction, params.max_push) * d / g;
  return out;
}

Matrix3d InverseRightJacobian(const Vector3d& theta) {
  const double t = theta.norm();
  // The coefficient's Taylor series 1/12 + t^2/720 near 0, where it cancels.
  const double c = t < 1e-4
                       ? 1.0 / 12.0 + t * t / 720.0
                       : 1.0 / (t * t) - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  const Matrix3d k = CrossMatrix(theta);
  return Matrix3d::Identity() + 0.5 * k + c * k * k;
}

// tau = I_w y, y = Psi w0^2 theta - 2 zeta w0 omega, theta = log(H R^T): under
// R -> exp([dtheta]x) R, H R^T -> (H R^T) exp(-[dtheta]x), so
// dtheta_err = -J_r^-1(theta) dtheta, and I_w -> I_w + [dtheta]x I_w - I_w [dtheta]x.
TorquePartials AssemblyTorqueJacobian(const GuidanceParams& params, double psi,
                                      const Matrix3d& inertia_world,
                                      const Matrix3d& rotation, const Matrix3d& held,
                                      const Vector3d& omega) {
  const Eigen::AngleAxisd error(held * rotation.transpose());
  const Vector3d theta = error.angle() * error.axis();
  const double w0 = params.torque_frequency;
  const Vector3d y =
      psi * w0 * w0 * theta - 2.0 * params.torque_damping_ratio * w0 * omega;
  TorquePartials out;
  out.rotation = -CrossMatrix(inertia_world * y) + inertia_world * CrossMatrix(y) -
                 psi * w0 * w0 * inertia_world * InverseRightJacobian(theta);
  out.omega = -2.0 * params.torque_damping_ratio * w0 * inertia_world;
  return out;
}

}  // namespace vahf::guidance
