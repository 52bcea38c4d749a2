// The fatigue factor of Sec. 3.2.3: the operator's work A (Eq. 4) and the
// fatigue coefficient Psi_c (Eq. 6).
//
// Units. Eq. 4 multiplies a force in N by distances in m, so A comes out in
// joules, as the paper's symbol list says. Eq. 6 compares A with 1600, the
// upper limit of a working day's energy expenditure in kcal (1400-1600 kcal per
// 8 h, Institute of Health of the Chinese Academy of Medical Sciences, the
// paper's [37]). vahf keeps A in joules and converts that limit explicitly:
// A_max = 1600 kcal * 4184 J/kcal (thermochemical calorie, ISO 80000-5) =
// 6.6944 MJ. The paper's Table 1 lists A in "kcal" with values 1.8-7.9 over
// 9 s, which is neither (reference/paper/NOTES.md).
#pragma once

#include <Eigen/Core>

namespace vahf::human {

inline constexpr double kJoulePerKcal = 4184.0;  // thermochemical calorie, ISO 80000-5

struct FatigueParams {
  double k = 6.0;  // K of Eq. 4: biomechanical coefficient, "equal to 6" (Sec. 3.2.3)
  double a_max = 1600.0 * kJoulePerKcal;  // J, the 1600 of Eq. 6 in SI
  // Psi_c at or below this floor means the operator is exhausted: the trial
  // ends with status exhausted (Eq. 5 divides by Psi_c).
  double psi_floor = 0.05;
};

// Travel of the part split as Eq. 4 needs it, metres.
struct Travel {
  double lifted = 0.0;      // H_n, upward
  double horizontal = 0.0;  // L
  double lowered = 0.0;     // H_0, downward
};

// Splits a displacement (world frame, z up) into lifted, horizontal and
// lowered travel.
Travel TravelOf(const Eigen::Vector3d& displacement);

// Eq. 4: A = (F H_n + F L / 9 + F H_0 / 2) K n, joules, for a force of size F
// (N) over `travel`, n equal cycles.
double WorkEq4(double force, const Travel& travel, double k, double cycles = 1.0);

// Eq. 6: Psi_c = (A_max - A) / A_max for 0 <= A <= A_max. Past A_max the
// paper's equation is undefined; vahf holds Psi_c at 0 (no strength left).
double FatigueCoefficient(double work, double a_max);

// True when the operator is exhausted: Psi_c <= psi_floor.
bool IsExhausted(double psi, double psi_floor);

}  // namespace vahf::human
