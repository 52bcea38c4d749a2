// The curves of Figs. 3-5: plateaus where the paper's text puts them (f = 1
// for Ang in [30, 45] deg, g = 1 for Anp in [30, 90] deg, r = 1 up to D1) and
// the breakpoints D1 = 0.85 l, D2 = 0.39 h, D3 = 0.68 h of Sec. 3.2.2.
#include "vahf/human/factor_curves.h"

#include <gtest/gtest.h>

namespace vahf::human {
namespace {

TEST(SightCurve, PlateauOfSec321) {
  const PiecewiseLinear f = DefaultSightCurve().Build();
  EXPECT_DOUBLE_EQ(f(30.0), 1.0);
  EXPECT_DOUBLE_EQ(f(37.5), 1.0);
  EXPECT_DOUBLE_EQ(f(45.0), 1.0);
  EXPECT_LT(f(46.0), 1.0);  // "the estimation decreases over 45 deg"
  EXPECT_LT(f(29.0), 1.0);
  EXPECT_DOUBLE_EQ(f(0.0), 0.5);
  EXPECT_DOUBLE_EQ(f(180.0), 0.0);
  EXPECT_DOUBLE_EQ(f(112.5), 0.5);  // halfway down the 45..180 ramp
}

TEST(GlanceCurve, PlateauOfSec322) {
  const PiecewiseLinear g = DefaultGlanceCurve().Build();
  EXPECT_DOUBLE_EQ(g(30.0), 1.0);
  EXPECT_DOUBLE_EQ(g(90.0), 1.0);
  EXPECT_LT(g(91.0), 1.0);  // looking up is uncomfortable
  EXPECT_DOUBLE_EQ(g(135.0), 0.5);
}

TEST(PlateauCurve, Violations) {
  EXPECT_TRUE(DefaultSightCurve().Violation().empty());
  const PlateauCurve reversed{0.5, 50, 40, 0}, high{1.5, 30, 40, 0},
      at_zero{0.5, 0, 40, 0};
  EXPECT_NE(reversed.Violation().find("plateau"), std::string::npos);
  EXPECT_NE(high.Violation().find("value_at_0"), std::string::npos);
  EXPECT_NE(at_zero.Violation().find("0 < plateau_from_deg"), std::string::npos);
}

TEST(ReachCurve, BreakpointsOfSec322) {
  const ReachCurve reach;
  const double l = 0.74, h = 1.75;
  const auto d = reach.BreakpointsFor(l, h);
  EXPECT_DOUBLE_EQ(d.d1, 0.85 * l);
  EXPECT_DOUBLE_EQ(d.d2, 0.39 * h);
  EXPECT_DOUBLE_EQ(d.d3, 0.68 * h);
  const PiecewiseLinear r = reach.Build(l, h);
  EXPECT_DOUBLE_EQ(r(0.3), 1.0);
  EXPECT_DOUBLE_EQ(r(d.d1), 1.0);
  EXPECT_DOUBLE_EQ(r(d.d2), 0.5);
  EXPECT_DOUBLE_EQ(r(d.d3), 0.0);
  EXPECT_DOUBLE_EQ(r(2.0), 0.0);  // beyond D3: unreachable with any posture
  EXPECT_GT(r(0.5 * (d.d1 + d.d2)), r(0.5 * (d.d2 + d.d3)));
}

TEST(ReachCurve, BreakpointsMustIncreaseForTheOperator) {
  // A long arm on a short operator: D1 = 0.85 * 0.95 = 0.8075 > D2 = 0.39 * 1.6 = 0.624.
  const std::string v = ReachCurve{}.Violation(0.95, 1.6);
  EXPECT_NE(v.find("need 0 < D1 < D2 < D3"), std::string::npos) << v;
  EXPECT_NE(v.find("0.8075"), std::string::npos) << v;
  EXPECT_TRUE(ReachCurve{}.Violation(0.74, 1.75).empty());
}

}  // namespace
}  // namespace vahf::human
