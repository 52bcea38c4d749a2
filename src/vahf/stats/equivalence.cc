#include "vahf/stats/equivalence.h"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>

#include "vahf/core/error.h"
#include "vahf/stats/internal/checks.h"

namespace vahf::stats {

TostResult EquivalenceTest(const std::vector<double>& a, const std::vector<double>& b,
                           double margin) {
  if (!(margin > 0 && std::isfinite(margin)))
    throw ComputationError(ComputationError::Reason::kOutOfDomain,
                           "EquivalenceTest: the margin must be finite and > 0");
  TostResult r;
  r.welch = WelchTTest(a, b);
  r.margin = margin;
  const double d = r.welch.mean_difference, se = r.welch.standard_error, df = r.welch.df;
  // H0a: d <= -margin (reject for large t), H0b: d >= margin (reject for small t).
  const double p_lower = gsl_cdf_tdist_Q((d + margin) / se, df);
  const double p_upper = gsl_cdf_tdist_P((d - margin) / se, df);
  r.p = std::max(p_lower, p_upper);
  const double half = TwoSidedStudentT(df, 0.90) * se;
  r.ci90 = {d - half, d + half};
  return r;
}

double AreaValidationMetric(const std::vector<double>& a, const std::vector<double>& b) {
  internal::RequireFinite(a, "AreaValidationMetric", "a");
  internal::RequireFinite(b, "AreaValidationMetric", "b");
  internal::RequireSize(a, 1, "AreaValidationMetric", "a");
  internal::RequireSize(b, 1, "AreaValidationMetric", "b");
  std::vector<double> sa = a, sb = b;
  std::sort(sa.begin(), sa.end());
  std::sort(sb.begin(), sb.end());
  // Both empirical CDFs are step functions; between consecutive points of the
  // pooled sample their difference is constant.
  std::vector<double> pooled = sa;
  pooled.insert(pooled.end(), sb.begin(), sb.end());
  std::sort(pooled.begin(), pooled.end());
  const double na = static_cast<double>(sa.size()), nb = static_cast<double>(sb.size());
  double area = 0;
  std::size_t ia = 0, ib = 0;
  for (std::size_t k = 0; k + 1 < pooled.size(); ++k) {
    const double x = pooled[k];
    while (ia < sa.size() && sa[ia] <= x) ++ia;
    while (ib < sb.size() && sb[ib] <= x) ++ib;
    area += std::fabs(static_cast<double>(ia) / na - static_cast<double>(ib) / nb) *
            (pooled[k + 1] - x);
  }
  return area;
}

}  // namespace vahf::stats
