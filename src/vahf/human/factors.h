// The human factors of Sec. 3.2 as pure functions: visibility V (Eq. 1), the
// vision coefficient eta (Eq. 2), the comfort coefficient lambda_c (Eq. 3), and
// the angles and distance that the curves f, g and r take.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "vahf/core/piecewise_linear.h"
#include "vahf/human/operator_model.h"

namespace vahf::human {

// Eq. 1: V = V_a / V_b, V_a the pixels of the assembling part that are seen
// with every assembled part shown, V_b its pixels when it alone is shown.
// V_b = 0 (the part is behind the eye or out of view) is defined as V = 0: the
// operator sees none of the part, the worst visibility. Requires
// 0 <= V_a <= V_b.
double Visibility(std::int64_t visible_pixels, std::int64_t part_pixels);

// Eq. 2: eta = 1 - V f.
double VisionCoefficient(double V, double f);

// Eq. 3: lambda_c = 1 - (r + g) / 2 * V.
double ComfortCoefficient(double r, double g, double V);

// Angle in degrees, in [0, 180], between two non-zero vectors.
double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// Ang of Sec. 3.2.1: the angle between the eye-sight direction (eye to part)
// and the part's direction of motion, degrees in [0, 180].
double SightAngleDeg(const Posture& posture, const Eigen::Vector3d& part_centre,
                     const Eigen::Vector3d& motion_direction);

// Anp of Sec. 3.2.2, degrees in [0, 180]. The paper's "angle between eye-sight
// direction and the plane of the body" must reach 180 and be below 90 when
// looking down, so vahf measures it in the body plane's sagittal section: the
// angle between the sight line and the body's down axis (Posture::down).
// Looking straight down along the body gives 0, level gaze 90, straight up 180.
double GlanceAngleDeg(const Posture& posture, const Eigen::Vector3d& part_centre);

// The distance for r (Sec. 5.1): max(|P_rs - P|, |P_ls - P|), metres.
double ShoulderDistance(const Posture& posture, const Eigen::Vector3d& part_centre);

// The curves a trial evaluates, built once per operator.
struct FactorCurves {
  PiecewiseLinear sight;   // f(Ang), Fig. 3
  PiecewiseLinear reach;   // r(distance), Fig. 4
  PiecewiseLinear glance;  // g(Anp), Fig. 5
};

// Every factor at one decision instant.
struct FactorValues {
  double V = 1.0;
  double sight_angle_deg = 0.0;  // Ang
  double f = 1.0;
  double eta = 0.0;
  double shoulder_distance = 0.0;  // m
  double r = 1.0;
  double glance_angle_deg = 90.0;  // Anp
  double g = 1.0;
  double lambda_c = 0.0;
};

// Evaluates f, r, g, eta and lambda_c for a part at `part_centre` moving along
// `motion_direction` (non-zero) with visibility V.
FactorValues EvaluateFactors(const FactorCurves& curves, const Posture& posture,
                             const Eigen::Vector3d& part_centre,
                             const Eigen::Vector3d& motion_direction, double V);

}  // namespace vahf::human
