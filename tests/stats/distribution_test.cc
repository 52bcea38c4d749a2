// Quantiles, the two-sample Kolmogorov-Smirnov distance and its p-value, and
// the shift a KS distance amounts to: hand-computed samples, and Kolmogorov's
// series evaluated with mpmath (30 digits) for the p-values.
#include "vahf/stats/distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "refusal.h"

namespace vahf::stats {
namespace {

TEST(Quantile, InterpolatesBetweenOrderStatistics) {
  const std::vector<double> xs = {4, 1, 3, 2};  // unsorted on purpose
  EXPECT_DOUBLE_EQ(Quantile(xs, 0.0), 1);
  EXPECT_DOUBLE_EQ(Quantile(xs, 1.0), 4);
  EXPECT_DOUBLE_EQ(Quantile(xs, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(Quantile(xs, 0.1), 1.3);  // h = 3 * 0.1: 1 + 0.3 * (2 - 1)
  EXPECT_DOUBLE_EQ(Quantile(xs, 0.9), 3.7);
  EXPECT_DOUBLE_EQ(Quantile({7.5}, 0.9), 7.5);
}

TEST(Quantile, RefusesWhatIsUndefined) {
  EXPECT_EQ(RefusalOf([] { Quantile({}, 0.5); }).reason, "too few values");
  EXPECT_EQ(RefusalOf([] { Quantile({1, 2}, 1.5); }).reason, "out of domain");
  EXPECT_EQ(RefusalOf([] { Quantile({1, NAN}, 0.5); }).reason, "out of domain");
}

TEST(KolmogorovSmirnov, DistanceOfKnownSamples) {
  // F_a - F_b after 1, 2, 3, 4, 5, 6: .25, .5, .5, .5, .25, 0.
  EXPECT_DOUBLE_EQ(KolmogorovSmirnovTest({1, 2, 3, 4}, {3, 4, 5, 6}).distance, 0.5);
  // Disjoint samples: 1; identical ones: 0, with p = 1.
  EXPECT_DOUBLE_EQ(KolmogorovSmirnovTest({1, 2}, {3, 4, 5}).distance, 1.0);
  const KolmogorovSmirnov same = KolmogorovSmirnovTest({3, 1, 2}, {1, 2, 3});
  EXPECT_EQ(same.distance, 0.0);
  EXPECT_EQ(same.p_value, 1.0);
  // Ties across the samples move both functions at once: after 1, 2/3 - 1/3.
  EXPECT_DOUBLE_EQ(KolmogorovSmirnovTest({1, 1, 2}, {1, 2, 2}).distance, 1.0 / 3);
  // Symmetric in its arguments.
  EXPECT_DOUBLE_EQ(KolmogorovSmirnovTest({3, 4, 5, 6}, {1, 2, 3, 4}).distance, 0.5);
}

TEST(KolmogorovSmirnov, StudentSleepDataWithStephensCorrection) {
  // The two groups of Student (1908): D = 0.4 (after 0.8: 7/10 - 3/10);
  // n_e = 5, lambda = (sqrt 5 + 0.12 + 0.11 / sqrt 5) 0.4 = 0.96210458920;
  // Q(lambda) = 0.312852676017 (mpmath).
  const KolmogorovSmirnov r =
      KolmogorovSmirnovTest({0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0},
                            {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4});
  EXPECT_DOUBLE_EQ(r.distance, 0.4);
  EXPECT_DOUBLE_EQ(r.effective_n, 5.0);
  EXPECT_NEAR(r.p_value, 0.312852676016956, 1e-12);
}

TEST(KolmogorovQ, MatchesTheSeriesOnBothBranches) {
  // 2 sum (-1)^(j-1) exp(-2 j^2 lambda^2), mpmath to 30 digits.
  EXPECT_EQ(KolmogorovQ(0.0), 1.0);
  EXPECT_NEAR(KolmogorovQ(0.3), 0.999990694198665, 1e-13);
  EXPECT_NEAR(KolmogorovQ(0.5), 0.963945243664875, 1e-13);
  EXPECT_NEAR(KolmogorovQ(0.8), 0.544142411574198, 1e-13);
  EXPECT_NEAR(KolmogorovQ(1.0), 0.269999671677355, 1e-13);
  EXPECT_NEAR(KolmogorovQ(1.1799), 0.123512049711887, 1e-13);  // small-lambda branch
  EXPECT_NEAR(KolmogorovQ(1.18), 0.123453809429766, 1e-13);    // alternating branch
  EXPECT_NEAR(KolmogorovQ(1.358), 0.0500267973344470, 1e-13);  // the 5 % point
  EXPECT_NEAR(KolmogorovQ(2.0), 0.000670925255779695, 1e-15);
  EXPECT_EQ(RefusalOf([] { KolmogorovQ(-0.1); }).reason, "out of domain");
  EXPECT_EQ(RefusalOf([] { KolmogorovQ(NAN); }).reason, "out of domain");
}

// The sample 1, 2, 4, 7 shifted by delta: windows (x - delta, x] hold one
// point for delta in (0, 1], two (2 and 1) up to 2, three (4, 2, 1) up to
// 3, and all four beyond 6.
TEST(KsShift, DistanceOfTheSampleFromItselfShifted) {
  const std::vector<double> xs = {7, 1, 4, 2};
  EXPECT_EQ(KsDistanceOfShift(xs, 0.0), 0.0);
  EXPECT_EQ(KsDistanceOfShift(xs, 0.5), 0.25);
  EXPECT_EQ(KsDistanceOfShift(xs, 1.0), 0.25);
  EXPECT_EQ(KsDistanceOfShift(xs, 1.5), 0.5);
  EXPECT_EQ(KsDistanceOfShift(xs, 3.5), 0.75);
  EXPECT_EQ(KsDistanceOfShift(xs, 6.5), 1.0);
  // The same as the two-sample statistic of the sample and its shifted copy.
  for (double delta : {0.5, 1.5, 2.5, 3.5, 5.5, 6.5}) {
    std::vector<double> shifted = xs;
    for (double& x : shifted) x += delta;
    EXPECT_EQ(KsDistanceOfShift(xs, delta), KolmogorovSmirnovTest(xs, shifted).distance)
        << delta;
  }
}

TEST(KsShift, EquivalentShiftIsTheSmallestShiftReachingTheDistance) {
  const std::vector<double> xs = {7, 1, 4, 2};
  EXPECT_EQ(KsEquivalentShift(xs, 0.0), 0.0);
  EXPECT_EQ(KsEquivalentShift(xs, 0.25), 0.0);         // any difference at all gives 1/n
  EXPECT_EQ(KsEquivalentShift(xs, 0.5), 1.0);          // 2 - 1
  EXPECT_EQ(KsEquivalentShift(xs, 0.75), 3.0);         // 4 - 1
  EXPECT_EQ(KsEquivalentShift(xs, 1.0), 6.0);          // 7 - 1
  EXPECT_EQ(KsEquivalentShift(xs, 0.5 + 1e-15), 1.0);  // a distance's rounding
  EXPECT_EQ(KsEquivalentShift({3.0}, 1.0), 0.0);
  // Just above it the shifted sample reaches the distance; at it, not yet.
  for (double d : {0.5, 0.75, 1.0}) {
    const double shift = KsEquivalentShift(xs, d);
    EXPECT_GE(KsDistanceOfShift(xs, shift + 1e-9), d) << d;
    EXPECT_LT(KsDistanceOfShift(xs, shift), d) << d;
  }
  EXPECT_EQ(RefusalOf([&] { KsEquivalentShift(xs, 1.5); }).reason, "out of domain");
  EXPECT_EQ(RefusalOf([] { KsEquivalentShift({}, 0.5); }).reason, "too few values");
  EXPECT_EQ(RefusalOf([&] { KsDistanceOfShift(xs, -1.0); }).reason, "out of domain");
}

}  // namespace
}  // namespace vahf::stats
