// The warnings record: counts add, the first occurrence's time and detail
// stay, sums over trials add kind by kind, and the summary names each kind.
#include "vahf/core/warnings.h"

#include <gtest/gtest.h>

namespace vahf {
namespace {

TEST(Warnings, FirstOccurrenceStaysAndCountsAdd) {
  Warnings w;
  EXPECT_TRUE(w.empty());
  EXPECT_EQ(w.Summary(), "none");
  w.Note(WarningKind::kPenetrationBound, 0.25, "depth 4 um > 2.8 um");
  w.Note(WarningKind::kPenetrationBound, 0.5, "depth 9 um > 2.8 um", 3);
  w.Note(WarningKind::kStepSizeFloor, 0.1, "h = 1e-12 s", 0);  // nothing happened
  const WarningEntry& e = w.at(WarningKind::kPenetrationBound);
  EXPECT_EQ(e.count, 4);
  EXPECT_EQ(e.first_time, 0.25);
  EXPECT_EQ(e.detail, "depth 4 um > 2.8 um");
  EXPECT_EQ(w.at(WarningKind::kStepSizeFloor).count, 0);
  EXPECT_EQ(w.total(), 4);
  EXPECT_EQ(w.Summary(),
            "penetration_bound 4 (first at t = 0.25 s: depth 4 um > 2.8 um)");
}

TEST(Warnings, SumsAddKindByKind) {
  Warnings a, b, sum;
  a.Note(WarningKind::kNonFiniteState, 1.0, "nan");
  b.Note(WarningKind::kNonFiniteState, 0.5, "inf", 2);
  b.Note(WarningKind::kIntegratorRetry, 0.2, "convergence failure");
  sum.Add(a);
  sum.Add(b);
  EXPECT_EQ(sum.at(WarningKind::kNonFiniteState).count, 3);
  EXPECT_EQ(sum.at(WarningKind::kNonFiniteState).detail, "nan");  // first summed
  EXPECT_EQ(sum.at(WarningKind::kIntegratorRetry).count, 1);
  EXPECT_EQ(sum.total(), 4);
  EXPECT_STREQ(WarningName(WarningKind::kIntegratorFailure), "integrator_failure");
  EXPECT_STREQ(WarningName(WarningKind::kRest), "rest");
}

}  // namespace
}  // namespace vahf
