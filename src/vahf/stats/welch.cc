#include "vahf/stats/welch.h"

#include <gsl/gsl_cdf.h>

#include <cmath>

#include "vahf/core/error.h"
#include "vahf/stats/internal/checks.h"

namespace vahf::stats {

WelchResult WelchTTest(const std::vector<double>& a, const std::vector<double>& b,
                       double level) {
  internal::RequireLevel(level, "WelchTTest");
  for (const auto& [xs, name] : {std::pair{&a, "a"}, std::pair{&b, "b"}}) {
    internal::RequireFinite(*xs, "WelchTTest", name);
    internal::RequireSize(*xs, 2, "WelchTTest", name);
  }
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  const double sa = SampleStandardDeviation(a), sb = SampleStandardDeviation(b);
  const double va = sa * sa / na, vb = sb * sb / nb;  // squared standard errors
  if (va == 0 && vb == 0) {
    throw ComputationError(
        ComputationError::Reason::kZeroVariance,
        "WelchTTest: both samples have zero variance: the t statistic is undefined");
  }
  WelchResult r;
  r.level = level;
  r.mean_difference = Mean(a) - Mean(b);
  r.standard_error = std::sqrt(va + vb);
  r.t = r.mean_difference / r.standard_error;
  r.df = (va + vb) * (va + vb) / (va * va / (na - 1) + vb * vb / (nb - 1));
  r.p_less = gsl_cdf_tdist_P(r.t, r.df);
  r.p_greater = gsl_cdf_tdist_Q(r.t, r.df);
  r.p_two_sided = 2.0 * gsl_cdf_tdist_Q(std::fabs(r.t), r.df);
  const double half = TwoSidedStudentT(r.df, level) * r.standard_error;
  r.ci = {r.mean_difference - half, r.mean_difference + half};
  return r;
}

}  // namespace vahf::stats
