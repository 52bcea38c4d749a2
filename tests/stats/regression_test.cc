// The least-squares line with the slope's standard error and t interval,
// against a hand computation; exact lines and degenerate inputs.
#include "vahf/stats/regression.h"

#include <gtest/gtest.h>

#include <cmath>

#include "refusal.h"

namespace vahf::stats {
namespace {

TEST(FitLine, HandComputed) {
  // x = 1..5, y = {2, 4, 5, 4, 5}: mean x 3, mean y 4, Sxx = 10, Sxy = 6, so
  // slope 0.6 and intercept 2.2. Residuals -0.8, 0.6, 1.0, -0.6, -0.2: SSE 2.4,
  // s^2 = 2.4 / 3 = 0.8, se(slope) = sqrt(0.8 / 10) = 0.2828427. With
  // t(3, 0.975) = 3.182446305: CI 0.6 -+ 0.9001317 = (-0.3001317, 1.5001317).
  const LinearFit f = FitLine({1, 2, 3, 4, 5}, {2, 4, 5, 4, 5});
  EXPECT_NEAR(f.slope, 0.6, 1e-14);
  EXPECT_NEAR(f.intercept, 2.2, 1e-14);
  EXPECT_NEAR(f.residual_sum_of_squares, 2.4, 1e-13);
  EXPECT_EQ(f.df, 3.0);
  EXPECT_NEAR(f.slope_standard_error, std::sqrt(0.08), 1e-14);
  EXPECT_NEAR(f.slope_ci.lower, -0.300131745291274, 1e-12);
  EXPECT_NEAR(f.slope_ci.upper, 1.50013174529127, 1e-12);
}

TEST(FitLine, PointsOnALineHaveNoSpread) {
  const LinearFit f = FitLine({0, 1, 2, 3}, {1, 3, 5, 7});
  EXPECT_DOUBLE_EQ(f.slope, 2.0);
  EXPECT_DOUBLE_EQ(f.intercept, 1.0);
  EXPECT_EQ(f.slope_standard_error, 0.0);
  EXPECT_EQ(f.slope_ci.lower, f.slope);
  EXPECT_EQ(f.slope_ci.upper, f.slope);
}

TEST(FitLine, DegenerateInputsThrow) {
  EXPECT_EQ(RefusalOf([] { FitLine({1, 2}, {1, 2}); }).reason, "too few values");
  EXPECT_EQ(RefusalOf([] { FitLine({1, 2, 3}, {1, 2}); }).reason, "out of domain");
  const Refusal r = RefusalOf([] { FitLine({4, 4, 4}, {1, 2, 3}); });
  EXPECT_EQ(r.reason, "zero variance");
  EXPECT_EQ(r.message,
            "FitLine: every x = 4: the slope is undefined when x does not vary");
}

}  // namespace
}  // namespace vahf::stats
