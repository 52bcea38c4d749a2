#include "vahf/stats/regression.h"

#include <fmt/format.h>
#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>

#include "vahf/core/error.h"
#include "vahf/stats/internal/checks.h"

namespace vahf::stats {

LinearFit FitLine(const std::vector<double>& x, const std::vector<double>& y,
                  double level) {
  internal::RequireLevel(level, "FitLine");
  internal::RequireFinite(x, "FitLine", "x");
  internal::RequireFinite(y, "FitLine", "y");
  if (x.size() != y.size()) {
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("FitLine: x has {} values, y has {}: must be equally many", x.size(),
                    y.size()));
  }
  internal::RequireSize(x, 3, "FitLine", "x");
  if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); })) {
    throw ComputationError(
        ComputationError::Reason::kZeroVariance,
        fmt::format("FitLine: every x = {}: the slope is undefined when x does not vary",
                    x.front()));
  }
  LinearFit f;
  f.level = level;
  double cov00 = 0, cov01 = 0, cov11 = 0;
  // gsl_fit_linear estimates the error variance as SSE / (n - 2) and returns
  // the covariance of (intercept, slope) scaled by it.
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &f.intercept, &f.slope, &cov00,
                 &cov01, &cov11, &f.residual_sum_of_squares);
  f.df = static_cast<double>(x.size()) - 2.0;
  f.slope_standard_error = std::sqrt(cov11);
  const double half = TwoSidedStudentT(f.df, level) * f.slope_standard_error;
  f.slope_ci = {f.slope - half, f.slope + half};
  return f;
}

}  // namespace vahf::stats
