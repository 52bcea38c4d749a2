// TOST and the area validation metric against values computed by hand or
// tabulated (R 4.2: pt(q, df, lower.tail = FALSE)).
#include "vahf/stats/equivalence.h"

#include <gtest/gtest.h>

#include "refusal.h"

namespace vahf::stats {
namespace {

// a and b both 1..5: difference 0, standard error sqrt(2.5/5 + 2.5/5) = 1,
// Welch df = 8. With margin m the two one-sided statistics are +-m, so
// p = P(T_8 > m).
TEST(EquivalenceTest, PIsTheLargerOneSidedTail) {
  const std::vector<double> a = {1, 2, 3, 4, 5}, b = {1, 2, 3, 4, 5};
  const TostResult one = EquivalenceTest(a, b, 1.0);
  EXPECT_DOUBLE_EQ(one.welch.standard_error, 1.0);
  EXPECT_NEAR(one.p, 0.1733, 1e-4);  // pt(1, 8, lower = F) = 0.17330
  const TostResult three = EquivalenceTest(a, b, 3.0);
  EXPECT_NEAR(three.p, 0.008535, 1e-6);  // pt(3, 8, lower = F) = 0.0085351
  // The 90 % interval: +- qt(0.95, 8) = 1.859548.
  EXPECT_NEAR(three.ci90.upper, 1.859548, 1e-6);
  EXPECT_NEAR(three.ci90.lower, -1.859548, 1e-6);
}

// A shift toward one side makes that side's test the weaker one.
TEST(EquivalenceTest, AShiftedSampleIsTestedOnItsNearSide) {
  const std::vector<double> a = {3, 4, 5, 6, 7}, b = {1, 2, 3, 4, 5};  // difference 2
  const TostResult r = EquivalenceTest(a, b, 3.0);
  EXPECT_DOUBLE_EQ(r.welch.mean_difference, 2.0);
  EXPECT_NEAR(r.p, 0.1733, 1e-4);  // (2 - 3) / 1 = -1: P(T_8 < -1)
  EXPECT_EQ(RefusalOf([&] { EquivalenceTest(a, b, 0.0); }).reason, "out of domain");
}

TEST(AreaValidationMetric, IsTheAreaBetweenTheEmpiricalDistributions) {
  EXPECT_DOUBLE_EQ(AreaValidationMetric({0.0}, {1.0}), 1.0);  // two point masses
  EXPECT_DOUBLE_EQ(AreaValidationMetric({0.0, 1.0}, {1.0, 0.0}), 0.0);
  // Equal means, different spreads: |0.5 - 0| on [0, 1), |0.5 - 1| on [1, 2).
  EXPECT_DOUBLE_EQ(AreaValidationMetric({0.0, 2.0}, {1.0}), 1.0);
  // A shift of every value by d gives area d.
  EXPECT_NEAR(AreaValidationMetric({1, 2, 3, 4}, {1.25, 2.25, 3.25, 4.25}), 0.25, 1e-15);
  EXPECT_EQ(RefusalOf([] { AreaValidationMetric({}, {1.0}); }).reason, "too few values");
}

}  // namespace
}  // namespace vahf::stats
