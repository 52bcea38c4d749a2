// The least-squares straight line y = intercept + slope * x with the standard
// error of the slope and its Student-t confidence interval (ordinary least
// squares with normal errors; Draper and Smith, Applied Regression Analysis,
// 3rd ed., Sec. 1.4), on gsl_fit_linear. Use: does the completion time rise
// across the fatigue segments (paper Sec. 5.4)?
#pragma once

#include <vector>

#include "vahf/stats/summary.h"

namespace vahf::stats {

struct LinearFit {
  double intercept = 0.0;
  double slope = 0.0;
  double slope_standard_error = 0.0;  // sqrt(s^2 / Sxx), s^2 = SSE / (n - 2)
  double df = 0.0;                    // n - 2
  double level = 0.95;
  Interval slope_ci;  // slope +- t(n-2, (1+level)/2) * slope_standard_error
  double residual_sum_of_squares = 0.0;
};

// x and y of equal length n >= 3 (n = 2 fits exactly and leaves no degree of
// freedom for the error), finite, and x not all equal (else the slope is
// undefined: kZeroVariance); these throw vahf::ComputationError. Points exactly on a line
// give a zero standard error and the single-point interval [slope, slope].
LinearFit FitLine(const std::vector<double>& x, const std::vector<double>& y,
                  double level = 0.95);

}  // namespace vahf::stats
