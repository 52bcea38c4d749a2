// The Wilson interval against a hand computation and its exact ends at 0 and n
// successes; Fisher's one-sided exact test against hypergeometric
// probabilities computed by hand, among them Fisher's own tea-tasting example.
#include "vahf/stats/proportion.h"

#include <gtest/gtest.h>

#include "refusal.h"

namespace vahf::stats {
namespace {

TEST(WilsonInterval, EightOfTen) {
  // p = 0.8, z = 1.959963985, z^2/n = 0.3841459: centre 0.7167401, half-width
  // 0.2265778: (0.4901625, 0.9433178) (Wilson 1927).
  const Interval ci = WilsonInterval({8, 10});
  EXPECT_NEAR(ci.lower, 0.490162471536642, 1e-12);
  EXPECT_NEAR(ci.upper, 0.943317848545625, 1e-12);
}

TEST(WilsonInterval, NoneAndAllSucceeded) {
  // At k = 0 the interval is [0, (z^2/n) / (1 + z^2/n)], at k = n its mirror.
  const Interval none = WilsonInterval({0, 10});
  EXPECT_EQ(none.lower, 0.0);
  EXPECT_NEAR(none.upper, 0.277532799862889, 1e-12);
  const Interval all = WilsonInterval({10, 10});
  EXPECT_NEAR(all.lower, 0.722467200137111, 1e-12);
  EXPECT_EQ(all.upper, 1.0);
  const Interval one = WilsonInterval({1, 20});
  EXPECT_NEAR(one.lower, 0.00888144880079539, 1e-13);
  EXPECT_NEAR(one.upper, 0.236131193446742, 1e-12);
}

TEST(WilsonInterval, BadCountsThrow) {
  EXPECT_EQ(RefusalOf([] { WilsonInterval({0, 0}); }).reason, "out of domain");
  EXPECT_EQ(RefusalOf([] { WilsonInterval({11, 10}); }).reason, "out of domain");
  EXPECT_EQ(RefusalOf([] { WilsonInterval({-1, 10}); }).reason, "out of domain");
  const Refusal level = RefusalOf([] { WilsonInterval({3, 10}, 0.0); });
  EXPECT_EQ(level.reason, "out of domain");
  EXPECT_EQ(level.message, "WilsonInterval: level = 0: must lie in (0, 1)");
}

TEST(FisherRateFellP, FishersTeaTasting) {
  // Fisher (1935), Sec. 2: 4 of 4 cups right against 0 of 4; the table
  // [[4, 0], [0, 4]] has probability 1 / C(8, 4) = 1/70.
  EXPECT_NEAR(FisherRateFellP({4, 4}, {0, 4}), 1.0 / 70.0, 1e-15);
}

TEST(FisherRateFellP, HandComputedTables) {
  // 10/10 then 5/10: 15 successes, 5 failures; the second group of 10 holds
  // at least 5 successes, so P(X <= 5) = P(X = 5) = C(15,5) C(5,5) / C(20,10)
  // = 3003 / 184756.
  EXPECT_NEAR(FisherRateFellP({10, 10}, {5, 10}), 3003.0 / 184756.0, 1e-15);
  // 9/10 then 7/10: 16 successes, 4 failures; P(X <= 7) = [C(16,6) C(4,4) +
  // C(16,7) C(4,3)] / C(20,10) = (8008 + 45760) / 184756 = 53768 / 184756.
  EXPECT_NEAR(FisherRateFellP({9, 10}, {7, 10}), 53768.0 / 184756.0, 1e-14);
  // The rate rose: no evidence that it fell.
  EXPECT_GT(FisherRateFellP({5, 10}, {10, 10}), 0.99);
  EXPECT_EQ(FisherRateFellP({10, 10}, {10, 10}), 1.0);
  EXPECT_EQ(FisherRateFellP({0, 7}, {0, 3}), 1.0);
}

TEST(FisherRateFellP, BadCountsThrow) {
  const Refusal r = RefusalOf([] { FisherRateFellP({3, 10}, {4, 0}); });
  EXPECT_EQ(r.reason, "out of domain");
  EXPECT_EQ(r.message,
            "FisherRateFellP: after = 4 of 0: needs trials >= 1 and 0 <= successes "
            "<= trials");
}

}  // namespace
}  // namespace vahf::stats
