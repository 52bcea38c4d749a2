#include "vahf/stats/summary.h"

#include <fmt/format.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

#include <cmath>

#include "vahf/core/error.h"
#include "vahf/stats/internal/checks.h"

namespace vahf::stats {

double Mean(const std::vector<double>& xs) {
  internal::RequireFinite(xs, "Mean");
  internal::RequireSize(xs, 1, "Mean");
  return gsl_stats_mean(xs.data(), 1, xs.size());
}

double SampleStandardDeviation(const std::vector<double>& xs) {
  internal::RequireFinite(xs, "SampleStandardDeviation");
  internal::RequireSize(xs, 2, "SampleStandardDeviation");
  // Two passes (GSL computes sum (x - mean)^2 about the given mean), so a
  // sample of identical values has exactly zero deviation.
  return gsl_stats_sd_m(xs.data(), 1, xs.size(), gsl_stats_mean(xs.data(), 1, xs.size()));
}

double TwoSidedStudentT(double df, double level) {
  internal::RequireLevel(level, "TwoSidedStudentT");
  if (!(df > 0) || !std::isfinite(df)) {
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("TwoSidedStudentT: df = {}: must be finite and > 0", df));
  }
  return gsl_cdf_tdist_Pinv(0.5 * (1.0 + level), df);
}

Interval MeanConfidenceInterval(const std::vector<double>& xs, double level) {
  internal::RequireLevel(level, "MeanConfidenceInterval");
  const double sd = SampleStandardDeviation(xs);
  const double mean = gsl_stats_mean(xs.data(), 1, xs.size());
  const double n = static_cast<double>(xs.size());
  const double half = TwoSidedStudentT(n - 1, level) * sd / std::sqrt(n);
  return {mean - half, mean + half};
}

Summary Summarize(const std::vector<double>& xs, double level) {
  internal::RequireLevel(level, "Summarize");
  internal::RequireFinite(xs, "Summarize");
  Summary s;
  s.n = xs.size();
  s.level = level;
  if (s.n >= 1) s.mean = Mean(xs);
  if (s.n >= 2) {
    s.sd = SampleStandardDeviation(xs);
    s.standard_error = *s.sd / std::sqrt(static_cast<double>(s.n));
    s.ci = MeanConfidenceInterval(xs, level);
  }
  return s;
}

}  // namespace vahf::stats
