// Agreement of a virtual sample with a lab sample (docs/experiments.md,
// "compare"): an equivalence test of the means against a stated margin, and
// the area validation metric between the two empirical distributions.
#pragma once

#include <vector>

#include "vahf/stats/summary.h"
#include "vahf/stats/welch.h"

namespace vahf::stats {

// Schuirmann's two one-sided tests (TOST; Schuirmann 1987, J. Pharmacokinet.
// Biopharm. 15:657-680) on Welch's statistic: H0 |mean(a) - mean(b)| >=
// margin against H1 |mean(a) - mean(b)| < margin. p is the larger of the two
// one-sided p-values; equivalence is shown at level alpha when p < alpha,
// which is when the (1 - 2 alpha) Welch interval of the difference lies inside
// (-margin, margin). Needs what WelchTTest needs, and margin > 0.
struct TostResult {
  WelchResult welch;  // the difference, its standard error and 95 % interval
  double margin = 0;
  double p = 1;   // max of the two one-sided p-values
  Interval ci90;  // the (1 - 2 alpha) = 90 % interval of the difference
};
TostResult EquivalenceTest(const std::vector<double>& a, const std::vector<double>& b,
                           double margin);

// The area validation metric (Ferson, Oberkampf and Ginzburg 2008, Comput.
// Methods Appl. Mech. Eng. 197:2408-2430, Eq. 8): the area between the two
// empirical distribution functions, integral |F_a(x) - F_b(x)| dx, in the
// unit of the data. 0 only when the samples have one distribution; for two
// point masses it is the distance between them. Each sample needs n >= 1
// finite values.
double AreaValidationMetric(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace vahf::stats
