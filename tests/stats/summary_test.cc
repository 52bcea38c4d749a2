// Mean, sample standard deviation and the Student-t interval for the mean
// against values computed by hand and a published one; n = 0 and 1, zero
// variance and bad arguments give their documented results.
#include "vahf/stats/summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "refusal.h"

namespace vahf::stats {
namespace {

// "reason: message" of what f refuses with.
template <class F>
std::string RefusalText(F&& f) {
  const Refusal r = RefusalOf(f);
  return r.reason + ": " + r.message;
}

TEST(Summary, HandComputedSample) {
  // {2, 4, 4, 4, 5, 5, 7, 9}: mean 40/8 = 5; sum of squared deviations
  // 9+1+1+1+0+0+4+16 = 32, so s = sqrt(32/7) = 2.138089935...;
  // t(7, 0.975) = 2.364624252, half-width 2.364624252 * s / sqrt(8) = 1.787487918.
  const std::vector<double> xs = {2, 4, 4, 4, 5, 5, 7, 9};
  EXPECT_DOUBLE_EQ(Mean(xs), 5.0);
  EXPECT_NEAR(SampleStandardDeviation(xs), std::sqrt(32.0 / 7.0), 1e-15);
  const Interval ci = MeanConfidenceInterval(xs);
  EXPECT_NEAR(ci.lower, 3.212512081763789, 1e-12);
  EXPECT_NEAR(ci.upper, 6.787487918236211, 1e-12);
  EXPECT_NEAR(TwoSidedStudentT(7, 0.95), 2.364624251592785, 1e-12);
}

TEST(Summary, StudentSleepDataMatchesThePublishedInterval) {
  // Student (1908), Biometrika 6:1-25: extra hours of sleep, drug 2 minus
  // drug 1, for ten patients (Cushny and Peebles). The paired t interval that
  // R prints for ?t.test's example: 95 % CI 0.7001142 .. 2.4598858, mean 1.58.
  const std::vector<double> d = {1.2, 2.4, 1.3, 1.3, 0.0, 1.0, 1.8, 0.8, 4.6, 1.4};
  const Summary s = Summarize(d);
  EXPECT_EQ(s.n, 10u);
  EXPECT_NEAR(*s.mean, 1.58, 1e-14);
  EXPECT_NEAR(*s.sd, 1.229995483, 1e-9);
  EXPECT_NEAR(*s.standard_error, 1.229995483 / std::sqrt(10.0), 1e-9);
  EXPECT_NEAR(s.ci->lower, 0.7001142, 5e-8);
  EXPECT_NEAR(s.ci->upper, 2.4598858, 5e-8);
}

TEST(Summary, OtherLevels) {
  const std::vector<double> xs = {2, 4, 4, 4, 5, 5, 7, 9};
  const Interval c90 = MeanConfidenceInterval(xs, 0.90);
  const Interval c99 = MeanConfidenceInterval(xs, 0.99);
  EXPECT_GT(c90.lower, MeanConfidenceInterval(xs).lower);
  EXPECT_LT(c99.lower, MeanConfidenceInterval(xs).lower);
  // t(7, 0.95) = 1.894578605 (two-sided 90 %).
  EXPECT_NEAR(c90.upper - 5.0, 1.894578605 * std::sqrt(32.0 / 7.0 / 8.0), 1e-8);
}

TEST(Summary, SmallSamplesLeaveUndefinedValuesEmpty) {
  const Summary none = Summarize({});
  EXPECT_EQ(none.n, 0u);
  EXPECT_FALSE(none.mean.has_value());
  EXPECT_FALSE(none.sd.has_value());
  EXPECT_FALSE(none.ci.has_value());
  const Summary one = Summarize({3.5});
  EXPECT_EQ(*one.mean, 3.5);
  EXPECT_FALSE(one.sd.has_value());
  EXPECT_FALSE(one.standard_error.has_value());
  EXPECT_FALSE(one.ci.has_value());
}

TEST(Summary, ZeroVarianceGivesAPointInterval) {
  const std::vector<double> same(5, 0.1);
  EXPECT_EQ(SampleStandardDeviation(same), 0.0);
  const Interval ci = MeanConfidenceInterval(same);
  EXPECT_EQ(ci.lower, Mean(same));
  EXPECT_EQ(ci.upper, Mean(same));
}

TEST(Summary, UndefinedValuesThrowWithTheirReason) {
  EXPECT_EQ(RefusalText([] { Mean({}); }),
            "too few values: Mean: xs has 0 values: needs at least 1");
  EXPECT_EQ(RefusalText([] { SampleStandardDeviation({1.0}); }),
            "too few values: SampleStandardDeviation: xs has 1 values: needs at least 2");
  EXPECT_EQ(RefusalText([] { MeanConfidenceInterval({1.0}); }),
            "too few values: SampleStandardDeviation: xs has 1 values: needs at least 2");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(RefusalText([&] {
              Summarize({1.0, nan});
            }),
            "out of domain: Summarize: xs[1] = nan: must be finite");
  EXPECT_EQ(RefusalText([] {
              MeanConfidenceInterval({1.0, 2.0}, 1.0);
            }),
            "out of domain: MeanConfidenceInterval: level = 1: must lie in (0, 1)");
  EXPECT_EQ(RefusalText([] { TwoSidedStudentT(0, 0.95); }),
            "out of domain: TwoSidedStudentT: df = 0: must be finite and > 0");
}

}  // namespace
}  // namespace vahf::stats
