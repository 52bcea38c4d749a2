// Tests of the paired tests (stats/paired.h) against values by hand: the
// paired t of d = {1, 2, 2, 3} (mean 2, sd sqrt(2/3), t = 4.899 on 3 df, whose
// upper tail is the closed form 1/2 - (x/(1+x^2) + atan x)/pi, x = t/sqrt 3)
// and McNemar's binomial tails.
#include "vahf/stats/paired.h"

#include <gtest/gtest.h>

#include <cmath>

#include "refusal.h"

namespace vahf::stats {
namespace {

TEST(PairedTTest, MatchesTheClosedFormOnThreeDegreesOfFreedom) {
  const PairedTResult r = PairedTTest({1, 2, 3, 4}, {0, 0, 1, 1});
  EXPECT_EQ(r.n, 4u);
  EXPECT_DOUBLE_EQ(r.mean_difference, 2.0);
  EXPECT_NEAR(r.standard_error, std::sqrt(2.0 / 3.0) / 2.0, 1e-15);
  EXPECT_NEAR(r.t, 4.898979485566356, 1e-12);
  EXPECT_DOUBLE_EQ(r.df, 3.0);
  EXPECT_NEAR(r.p_greater, 0.008138301729714303, 1e-12);
  EXPECT_NEAR(r.p_less, 1.0 - 0.008138301729714303, 1e-12);
  EXPECT_NEAR(r.p_two_sided, 2 * 0.008138301729714303, 1e-12);
  // t(0.975, 3) = 3.182446305284263.
  EXPECT_NEAR(r.ci.lower, 2.0 - 3.182446305284263 * r.standard_error, 1e-12);
  EXPECT_NEAR(r.ci.upper, 2.0 + 3.182446305284263 * r.standard_error, 1e-12);
}

// The pairing matters: the same samples unpaired differ by less than their
// spread, paired they differ by 1 every time but once.
TEST(PairedTTest, RemovesWhatThePairsShare) {
  const PairedTResult r = PairedTTest({11, 21, 31, 42}, {10, 20, 30, 40});
  EXPECT_DOUBLE_EQ(r.mean_difference, 1.25);
  EXPECT_LT(r.p_greater, 0.01);
}

TEST(PairedTTest, RefusesWhatIsUndefined) {
  // Unpaired; one pair; no spread in the differences.
  EXPECT_EQ(RefusalOf([] { PairedTTest({1, 2}, {1}); }).reason, "out of domain");
  EXPECT_EQ(RefusalOf([] { PairedTTest({1}, {0}); }).reason, "too few values");
  EXPECT_EQ(RefusalOf([] { PairedTTest({2, 3, 4}, {1, 2, 3}); }).reason, "zero variance");
  EXPECT_EQ(RefusalOf([] { PairedTTest({NAN, 3}, {1, 2}); }).reason, "out of domain");
}

TEST(McNemarRateFellP, IsTheBinomialTailOfTheDiscordantPairs) {
  // GSL takes the tail through the incomplete beta function: exact to rounding.
  EXPECT_NEAR(McNemarRateFellP(5, 0), 1.0 / 32.0, 1e-14);
  EXPECT_NEAR(McNemarRateFellP(3, 1), 5.0 / 16.0, 1e-14);  // P(X >= 3 | n = 4)
  EXPECT_DOUBLE_EQ(McNemarRateFellP(0, 4), 1.0);
  EXPECT_DOUBLE_EQ(McNemarRateFellP(0, 0), 1.0);  // nothing discordant
  EXPECT_EQ(RefusalOf([] { McNemarRateFellP(-1, 2); }).reason, "out of domain");
}

}  // namespace
}  // namespace vahf::stats
