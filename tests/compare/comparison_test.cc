// A quantity's comparison from its two samples: the verdicts and the
// sentences that carry them.
#include "vahf/compare/comparison.h"

#include <gtest/gtest.h>

namespace vahf::compare {
namespace {

calibrate::Target TimeTarget() {
  calibrate::Target t;
  t.spec.quantity = "assembly_time";
  t.spec.part = "peg";
  t.unit = "s";
  t.label = "assembly_time of peg";
  return t;
}

calibrate::TargetSamples Times(const std::vector<double>& times) {
  calibrate::TargetSamples s;
  for (double x : times) s.Add(true, x, "op");
  return s;
}

TEST(CompareSamples, TimesWithinTheMarginAgree) {
  const auto lab = Times({1.00, 1.02, 0.98, 1.01, 0.99, 1.00});
  const auto virt = Times({1.01, 1.00, 0.99, 1.02, 1.00, 0.98});
  const QuantityComparison q = CompareSamples(TimeTarget(), 0.05, lab, virt);
  ASSERT_TRUE(q.testable);
  EXPECT_TRUE(q.agree) << q.verdict;
  EXPECT_EQ(q.verdict.rfind("agree:", 0), 0u) << q.verdict;
  EXPECT_LT(q.tost_p, 0.05);
  ASSERT_TRUE(q.ks.has_value());
  EXPECT_GE(q.area_metric, 0.0);
}

TEST(CompareSamples, ADifferenceBeyondTheMarginIsNotShownToAgree) {
  const auto lab = Times({1.00, 1.02, 0.98, 1.01, 0.99, 1.00});
  const auto virt = Times({0.80, 0.82, 0.78, 0.81, 0.79, 0.80});
  const QuantityComparison q = CompareSamples(TimeTarget(), 0.05, lab, virt);
  EXPECT_FALSE(q.agree);
  EXPECT_EQ(q.verdict.rfind("not shown to agree:", 0), 0u) << q.verdict;
  EXPECT_NEAR(q.difference, -0.2, 1e-12);
  EXPECT_NEAR(q.area_metric, 0.2, 1e-12);  // a pure shift: the area is the shift
}

TEST(CompareSamples, TooFewTimesAreUntestableAndSaySo) {
  const QuantityComparison q =
      CompareSamples(TimeTarget(), 0.05, Times({1.0}), Times({1.0, 1.1, 0.9}));
  EXPECT_FALSE(q.testable);
  EXPECT_EQ(q.verdict.rfind("untestable:", 0), 0u) << q.verdict;
  EXPECT_NE(q.verdict.find("1 lab"), std::string::npos) << q.verdict;
}

TEST(CompareSamples, RatesAgreeOnlyWhenTheDataResolveTheMargin) {
  calibrate::Target t = TimeTarget();
  t.spec.quantity = "success_rate";
  t.unit = "1";
  calibrate::TargetSamples few_lab, few_virt, many_lab, many_virt;
  for (int i = 0; i < 10; ++i) few_lab.Add(i < 9, 1.0, "op"), few_virt.Add(i < 9, 1.0, "op");
  for (int i = 0; i < 1000; ++i)
    many_lab.Add(i < 900, 1.0, "op"), many_virt.Add(i < 900, 1.0, "op");
  // Equal rates of 0.9: ten trials a side cannot show agreement within 0.1,
  // a thousand can.
  EXPECT_FALSE(CompareSamples(t, 0.1, few_lab, few_virt).agree);
  const QuantityComparison many = CompareSamples(t, 0.1, many_lab, many_virt);
  EXPECT_TRUE(many.agree) << many.verdict;
  EXPECT_DOUBLE_EQ(many.difference, 0.0);
  EXPECT_FALSE(many.ks.has_value());
}

}  // namespace
}  // namespace vahf::compare
