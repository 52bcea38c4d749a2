#include "vahf/human/fatigue.h"

#include <algorithm>
#include <cmath>

#include "vahf/core/error.h"

namespace vahf::human {

Travel TravelOf(const Eigen::Vector3d& displacement) {
  Travel t;
  t.lifted = std::max(displacement.z(), 0.0);
  t.lowered = std::max(-displacement.z(), 0.0);
  t.horizontal = std::hypot(displacement.x(), displacement.y());
  return t;
}

double WorkEq4(double force, const Travel& travel, double k, double cycles) {
  VAHF_CHECK(force >= 0 && k >= 0 && cycles >= 0, "Eq. 4 takes non-negative F, K, n");
  return (force * travel.lifted + force * travel.horizontal / 9.0 +
          force * travel.lowered / 2.0) *
         k * cycles;
}

double FatigueCoefficient(double work, double a_max) {
  VAHF_CHECK(a_max > 0 && work >= 0, "Eq. 6 needs A >= 0 and A_max > 0");
  return std::clamp((a_max - work) / a_max, 0.0, 1.0);
}

bool IsExhausted(double psi, double psi_floor) { return psi <= psi_floor; }

}  // namespace vahf::human
