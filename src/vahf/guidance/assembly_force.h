// The operator's assembly force of Sec. 3.3: the estimated target T' (Eq. 5),
// its size in free motion (Eq. 7) and in contact (Eq. 8).
#pragma once

#include <Eigen/Core>

#include "vahf/rng/stream.h"

namespace vahf::guidance {

struct GuidanceParams {
  // kappa of Eqs. 7-8, N/m. The paper defers it to its ref. [14], which is not
  // available; a calibration target (issue: calibrate).
  double kappa = 400.0;
  // Damping b of F = kappa Psi (T' - T) - b v, N s/m (DESIGN.md decision 2:
  // an extension, without which the part oscillates about T').
  double damping = 40.0;
  // Scales of the vision error E_i, metres at eta = 1 (DESIGN.md decision 4):
  // along the line of sight (depth is hardest to judge) and across it.
  double vision_sigma_depth = 0.010;
  double vision_sigma_lateral = 0.003;
};

// Eq. 5: T' = T_t + (lambda_c / Psi_c) T_{i-t} + E_i with
// T_{i-t} = (c1 (x_i - x_t), c2 (y_i - y_t), c3 (z_i - z_t)), c_k uniform on
// [0, 1]. Requires psi > 0 (the trial ends as exhausted before Psi_c reaches
// its floor).
Eigen::Vector3d EstimatedTarget(const Eigen::Vector3d& target,
                                const Eigen::Vector3d& position, double lambda_c,
                                double psi, const Eigen::Vector3d& c,
                                const Eigen::Vector3d& vision_error);

// E_i: zero-mean Gaussian scaled by eta, sigma_depth along the unit sight line
// and sigma_lateral across it; n holds three standard normal draws.
Eigen::Vector3d VisionError(double eta, const Eigen::Vector3d& sight_direction,
                            double sigma_depth, double sigma_lateral,
                            const Eigen::Vector3d& n);

// Eq. 5 with its random numbers drawn from the trial's streams at this
// decision: c1..c3 from Purpose::kTargetEstimate, E_i from Purpose::kVisionError.
Eigen::Vector3d DrawEstimatedTarget(const GuidanceParams& params, rng::StreamKey key,
                                    std::uint64_t decision,
                                    const Eigen::Vector3d& target,
                                    const Eigen::Vector3d& position,
                                    const Eigen::Vector3d& sight_direction,
                                    double eta, double lambda_c, double psi);

// Eq. 7: F_AF = kappa Psi_c D_i, directed from T_i to T'_{i+1}; the vector.
Eigen::Vector3d FreeAssemblyForce(double kappa, double psi,
                                  const Eigen::Vector3d& position,
                                  const Eigen::Vector3d& estimated_target);

// Eq. 8: the direction is T_i T' with its component along the contact force
// F_C removed; the size is kappa Psi_c |that vector| + friction (N), the force
// needed to overcome friction. Zero when T_i T' is parallel to F_C.
Eigen::Vector3d ContactAssemblyForce(double kappa, double psi,
                                     const Eigen::Vector3d& position,
                                     const Eigen::Vector3d& estimated_target,
                                     const Eigen::Vector3d& contact_force,
                                     double friction);

}  // namespace vahf::guidance
