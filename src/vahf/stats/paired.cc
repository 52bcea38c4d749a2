#include "vahf/stats/paired.h"

#include <gsl/gsl_cdf.h>

#include <cmath>

#include "vahf/core/error.h"
#include "vahf/stats/internal/checks.h"

namespace vahf::stats {

PairedTResult PairedTTest(const std::vector<double>& a, const std::vector<double>& b,
                          double level) {
  internal::RequireLevel(level, "PairedTTest");
  internal::RequireFinite(a, "PairedTTest", "a");
  internal::RequireFinite(b, "PairedTTest", "b");
  if (a.size() != b.size())
    throw ComputationError(ComputationError::Reason::kOutOfDomain,
                           "PairedTTest: a and b differ in size: pairs need both");
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  internal::RequireSize(d, 2, "PairedTTest", "the differences");
  const double sd = SampleStandardDeviation(d);
  if (sd == 0)
    throw ComputationError(
        ComputationError::Reason::kZeroVariance,
        "PairedTTest: every difference is the same: the t statistic is undefined");
  PairedTResult r;
  r.n = d.size();
  r.level = level;
  r.mean_difference = Mean(d);
  r.standard_error = sd / std::sqrt(static_cast<double>(r.n));
  r.t = r.mean_difference / r.standard_error;
  r.df = static_cast<double>(r.n - 1);
  r.p_less = gsl_cdf_tdist_P(r.t, r.df);
  r.p_greater = gsl_cdf_tdist_Q(r.t, r.df);
  r.p_two_sided = 2.0 * gsl_cdf_tdist_Q(std::fabs(r.t), r.df);
  const double half = TwoSidedStudentT(r.df, level) * r.standard_error;
  r.ci = {r.mean_difference - half, r.mean_difference + half};
  return r;
}

double McNemarRateFellP(std::int64_t fell, std::int64_t rose) {
  if (fell < 0 || rose < 0)
    throw ComputationError(ComputationError::Reason::kOutOfDomain,
                           "McNemarRateFellP: counts are >= 0");
  const auto n = static_cast<unsigned int>(fell + rose);
  if (n == 0 || fell == 0) return 1.0;
  // P(X >= fell) = Q(fell - 1), X ~ Binomial(n, 1/2).
  return gsl_cdf_binomial_Q(static_cast<unsigned int>(fell - 1), 0.5, n);
}

}  // namespace vahf::stats
