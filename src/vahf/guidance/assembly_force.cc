#include "vahf/guidance/assembly_force.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "vahf/core/error.h"

namespace vahf::guidance {

Eigen::Vector3d EstimatedTarget(const Eigen::Vector3d& target,
                                const Eigen::Vector3d& position, double lambda_c,
                                double psi, const Eigen::Vector3d& c,
                                const Eigen::Vector3d& vision_error) {
  VAHF_CHECK(psi > 0, "Eq. 5 divides by Psi_c");
  const Eigen::Vector3d t_i_t = c.cwiseProduct(position - target);
  return target + (lambda_c / psi) * t_i_t + vision_error;
}

Eigen::Vector3d VisionError(double eta, const Eigen::Vector3d& sight_direction,
                            double sigma_depth, double sigma_lateral,
                            const Eigen::Vector3d& n) {
  const Eigen::Vector3d s = sight_direction.normalized();
  // Two unit vectors across the sight line: any orthonormal completion.
  const Eigen::Vector3d helper =
      std::abs(s.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d u = s.cross(helper).normalized();
  const Eigen::Vector3d w = s.cross(u);
  return eta * (sigma_depth * n.x() * s + sigma_lateral * (n.y() * u + n.z() * w));
}

Eigen::Vector3d DrawEstimatedTarget(const GuidanceParams& params, rng::StreamKey key,
                                    std::uint64_t decision, const Eigen::Vector3d& target,
                                    const Eigen::Vector3d& position,
                                    const Eigen::Vector3d& sight_direction, double eta,
                                    double lambda_c, double psi) {
  rng::Stream cs(key, decision, rng::Purpose::kTargetEstimate);
  const double c1 = cs.Uniform();
  const double c2 = cs.Uniform();
  const double c3 = cs.Uniform();
  rng::Stream ns(key, decision, rng::Purpose::kVisionError);
  const double n1 = ns.Normal();
  const double n2 = ns.Normal();
  const double n3 = ns.Normal();
  const Eigen::Vector3d e =
      VisionError(eta, sight_direction, params.vision_sigma_depth,
                  params.vision_sigma_lateral, Eigen::Vector3d(n1, n2, n3));
  return EstimatedTarget(target, position, lambda_c, psi, Eigen::Vector3d(c1, c2, c3), e);
}

Eigen::Vector3d FreeAssemblyForce(double kappa, double psi,
                                  const Eigen::Vector3d& position,
                                  const Eigen::Vector3d& estimated_target) {
  // kappa Psi D_i along the unit vector T_i T' is kappa Psi (T' - T_i).
  return kappa * psi * (estimated_target - position);
}

Eigen::Vector3d ContactAssemblyForce(double kappa, double psi,
                                     const Eigen::Vector3d& position,
                                     const Eigen::Vector3d& estimated_target,
                                     const Eigen::Vector3d& contact_force,
                                     double friction) {
  const Eigen::Vector3d to_target = estimated_target - position;
  Eigen::Vector3d direction = to_target;
  const double fc = contact_force.norm();
  if (fc > 0) {
    const Eigen::Vector3d n = contact_force / fc;
    direction -= to_target.dot(n) * n;
  }
  const double size = direction.norm();
  if (!(size > 0)) return Eigen::Vector3d::Zero();
  return (kappa * psi * size + friction) * (direction / size);
}

double FrictionPush(double friction, double max_push) {
  const double knee = 0.5 * max_push;
  if (!(max_push > 0 && friction > knee)) return friction;
  const double u = (friction - knee) / (max_push - knee);
  return knee + (max_push - knee) * u / std::cbrt(1.0 + u * u * u);
}

double FrictionPushSlope(double friction, double max_push) {
  const double knee = 0.5 * max_push;
  if (!(max_push > 0 && friction > knee)) return 1.0;
  const double u = (friction - knee) / (max_push - knee);
  const double c = std::cbrt(1.0 + u * u * u);
  return 1.0 / (c * c * c * c);  // (1 + u^3)^(-4/3)
}

double ForceDamping(const GuidanceParams& params, double psi, double mass) {
  return 2.0 * params.damping_ratio * std::sqrt(params.kappa * psi * mass);
}

Eigen::Vector3d WithdrawalTarget(const Eigen::Vector3d& position,
                                 const Eigen::Vector3d& target, double distance) {
  const Eigen::Vector3d away = position - target;
  const double size = away.norm();
  if (!(size > 0)) return position;
  return position + (distance / size) * away;
}

Eigen::Vector3d WithdrawalForce(const GuidanceParams& params, double psi, double mass,
                                const Eigen::Vector3d& position,
                                const Eigen::Vector3d& withdrawal_target,
                                const Eigen::Vector3d& velocity, double friction,
                                const Eigen::Vector3d& weight, double fade_length) {
  const double b = ForceDamping(params, psi, mass);
  const Eigen::Vector3d d = withdrawal_target - position;
  return params.kappa * psi * d - params.weight_support * weight +
         FrictionPush(friction, params.max_push) * d /
             std::sqrt(d.squaredNorm() + fade_length * fade_length) -
         b * velocity;
}

double ContactBlend(double normal_force, double blend_force) {
  const double s = std::clamp(normal_force / blend_force, 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

Eigen::Vector3d ImpedanceForce(const GuidanceParams& params, double psi, double mass,
                               const Eigen::Vector3d& position,
                               const Eigen::Vector3d& estimated_target,
                               const Eigen::Vector3d& velocity,
                               const FeltContact& contact, double blend_force,
                               const Eigen::Vector3d& weight, double fade_length) {
  const double b = ForceDamping(params, psi, mass);
  const Eigen::Vector3d to_target = estimated_target - position;
  const double fn = contact.normal_force.norm();
  const double w = ContactBlend(fn, blend_force);
  Eigen::Vector3d force =
      params.kappa * psi * to_target - (1.0 - w) * params.weight_support * weight;
  if (w > 0) {  // fn > 0, so the normal is defined
    const Eigen::Vector3d n = contact.normal_force / fn;
    const Eigen::Vector3d along = to_target - to_target.dot(n) * n;  // P (T' - T)
    force += -w * params.kappa * psi * to_target.dot(n) * n +
             w * FrictionPush(contact.friction, params.max_push) * along /
                 std::sqrt(along.squaredNorm() + fade_length * fade_length);
  }
  return force - b * velocity;
}

}  // namespace vahf::guidance
