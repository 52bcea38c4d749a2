// Success rates: the Wilson score interval for a proportion and Fisher's exact
// test for "the success rate fell" (docs/design.md decision 8: the assembly success
// rate counts completed trials over attempted ones), on GSL.
#pragma once

#include <cstdint>

#include "vahf/stats/summary.h"

namespace vahf::stats {

// `successes` of `trials` attempts; 0 <= successes <= trials.
struct Count {
  std::int64_t successes = 0;
  std::int64_t trials = 0;
};

// The Wilson score interval (Wilson 1927, JASA 22:209-212) for the success
// probability at `level` in (0, 1): with p = k/n and z = Phi^-1((1+level)/2),
//   (p + z^2/2n -+ z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n).
// Unlike the normal (Wald) interval it stays inside [0, 1] and is not empty at
// k = 0 or k = n, where its lower, respectively upper, end is exactly 0 or 1.
// trials >= 1.
Interval WilsonInterval(Count c, double level = 0.95);

// One-sided p-value of Fisher's exact test (Fisher, The Design of Experiments,
// 1935, Sec. 2) for H1: the success rate `after` is lower than `before`.
// Conditional on the margins of the 2x2 table, the successes of `after` are
// hypergeometric; p = P(X <= after.successes). Small p: the rate fell. Exact
// at any sample size, so valid for rates near 1 with few failures, where a
// two-proportion z-test is not. Both counts need trials >= 1; p = 1 when all
// trials, or none, succeeded in both.
double FisherRateFellP(Count before, Count after);

}  // namespace vahf::stats
