// Welch's t-test on Student's sleep data read as two independent groups: the
// values R prints for the example of ?t.test (t = -1.8608, df = 17.776,
// p = 0.07939, 95 % CI -3.3654832 .. 0.2054832), to the digits printed, and
// to 1e-10 against an mpmath evaluation of the t distribution (regularized
// incomplete beta, 30 digits).
#include "vahf/stats/welch.h"

#include <gtest/gtest.h>

#include <cmath>

#include "refusal.h"

namespace vahf::stats {
namespace {

// Student (1908), Biometrika 6:1-25: extra hours of sleep with drug 1 and 2.
const std::vector<double> kDrug1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
const std::vector<double> kDrug2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};

TEST(WelchTTest, StudentSleepData) {
  const WelchResult r = WelchTTest(kDrug1, kDrug2);
  EXPECT_NEAR(r.mean_difference, 0.75 - 2.33, 1e-14);
  EXPECT_NEAR(r.t, -1.8608, 5e-5);
  EXPECT_NEAR(r.df, 17.776, 5e-4);
  EXPECT_NEAR(r.p_two_sided, 0.07939, 5e-6);
  EXPECT_NEAR(r.ci.lower, -3.3654832, 5e-8);
  EXPECT_NEAR(r.ci.upper, 0.2054832, 5e-8);
  // mpmath, 30 digits.
  EXPECT_NEAR(r.t, -1.86081346748685, 1e-12);
  EXPECT_NEAR(r.df, 17.7764735161785, 1e-10);
  EXPECT_NEAR(r.p_two_sided, 0.0793941401873581, 1e-10);
  EXPECT_NEAR(r.p_less, 0.0396970700936791, 1e-10);
  EXPECT_NEAR(r.p_greater, 0.960302929906321, 1e-10);
}

TEST(WelchTTest, SwappingTheSamplesMirrorsTheResult) {
  const WelchResult ab = WelchTTest(kDrug1, kDrug2);
  const WelchResult ba = WelchTTest(kDrug2, kDrug1);
  EXPECT_DOUBLE_EQ(ba.t, -ab.t);
  EXPECT_DOUBLE_EQ(ba.df, ab.df);
  EXPECT_DOUBLE_EQ(ba.p_two_sided, ab.p_two_sided);
  EXPECT_DOUBLE_EQ(ba.p_greater, ab.p_less);
}

TEST(WelchTTest, OneConstantSampleIsDefined) {
  // b has no spread: se = s_a / sqrt(n_a) and df = n_a - 1, a one-sample test
  // of a against mean(b). a = {1, 2, 3}: mean 2, s = 1, t = (2 - 0)/(1/sqrt 3).
  const WelchResult r = WelchTTest({1, 2, 3}, {0, 0, 0, 0});
  EXPECT_NEAR(r.df, 2.0, 1e-14);
  EXPECT_NEAR(r.t, 2.0 * std::sqrt(3.0), 1e-14);
}

TEST(WelchTTest, UndefinedCasesThrow) {
  EXPECT_EQ(RefusalOf([] { WelchTTest({1, 1, 1}, {2, 2}); }).reason, "zero variance");
  const Refusal r = RefusalOf([] { WelchTTest({1.0}, {1, 2, 3}); });
  EXPECT_EQ(r.reason, "too few values");
  EXPECT_EQ(r.message, "WelchTTest: a has 1 values: needs at least 2");
}

}  // namespace
}  // namespace vahf::stats
