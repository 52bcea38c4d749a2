// Welch's two-sample t-test for a difference of means without assuming equal
// variances (Welch 1947, Biometrika 34:28-35), with the Welch-Satterthwaite
// degrees of freedom (Satterthwaite 1946, Biometrics Bulletin 2:110-114), on
// GSL's Student-t distribution. Use: virtual against lab completion times.
#pragma once

#include <vector>

#include "vahf/stats/summary.h"

namespace vahf::stats {

struct WelchResult {
  double mean_difference = 0.0;  // mean(a) - mean(b)
  double standard_error = 0.0;   // sqrt(s_a^2/n_a + s_b^2/n_b)
  double t = 0.0;                // mean_difference / standard_error
  double df = 0.0;               // Welch-Satterthwaite
  double p_two_sided = 1.0;      // H1: mean(a) != mean(b)
  double p_less = 0.5;           // H1: mean(a) < mean(b), P(T <= t)
  double p_greater = 0.5;        // H1: mean(a) > mean(b), P(T >= t)
  double level = 0.95;
  Interval ci;  // for mean(a) - mean(b) at `level`
};

// Each sample needs n >= 2 finite values. If one sample has zero variance the
// test is still defined (df = n - 1 of the other); if both have, the statistic
// is 0/0 or +-inf with 0 degrees of freedom, and this throws
// vahf::ComputationError with reason kZeroVariance.
WelchResult WelchTTest(const std::vector<double>& a, const std::vector<double>& b,
                       double level = 0.95);

}  // namespace vahf::stats
