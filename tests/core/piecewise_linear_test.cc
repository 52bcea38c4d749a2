// PiecewiseLinear: interpolation between knots, constant hold outside them,
// and rejection of knots that do not increase.
#include "vahf/core/piecewise_linear.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vahf {
namespace {

TEST(PiecewiseLinear, InterpolatesAndHolds) {
  const PiecewiseLinear c({{0.0, 0.5}, {30.0, 1.0}, {45.0, 1.0}, {180.0, 0.0}});
  EXPECT_DOUBLE_EQ(c(-10.0), 0.5);
  EXPECT_DOUBLE_EQ(c(0.0), 0.5);
  EXPECT_DOUBLE_EQ(c(15.0), 0.75);
  EXPECT_DOUBLE_EQ(c(30.0), 1.0);
  EXPECT_DOUBLE_EQ(c(40.0), 1.0);
  EXPECT_DOUBLE_EQ(c(112.5), 0.5);
  EXPECT_DOUBLE_EQ(c(180.0), 0.0);
  EXPECT_DOUBLE_EQ(c(500.0), 0.0);
}

TEST(PiecewiseLinear, SingleKnotIsConstant) {
  const PiecewiseLinear c({{1.0, 0.25}});
  EXPECT_DOUBLE_EQ(c(-1.0), 0.25);
  EXPECT_DOUBLE_EQ(c(3.0), 0.25);
}

TEST(PiecewiseLinear, ViolationNamesTheRule) {
  EXPECT_EQ(PiecewiseLinear::Violation({}), "a curve needs at least one knot");
  EXPECT_NE(
      PiecewiseLinear::Violation({{0, 0}, {0, 1}}).find("increase strictly (knot 1)"),
      std::string::npos);
  EXPECT_NE(PiecewiseLinear::Violation({{0, 0}, {1, NAN}}).find("not finite"),
            std::string::npos);
  EXPECT_TRUE(PiecewiseLinear::Violation({{0, 0}, {1, 1}}).empty());
}

TEST(PiecewiseLinearDeathTest, BadKnotsAreABug) {
  EXPECT_DEATH(PiecewiseLinear({{1.0, 0.0}, {0.0, 1.0}}), "increase strictly");
}

}  // namespace
}  // namespace vahf
