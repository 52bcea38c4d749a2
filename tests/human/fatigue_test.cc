// Eq. 4 (work, joules) and Eq. 6 (fatigue coefficient) with its behaviour at and
// past exhaustion.
#include "vahf/human/fatigue.h"

#include <gtest/gtest.h>

namespace vahf::human {
namespace {

TEST(TravelOf, SplitsUpDownAndAcross) {
  const Travel up = TravelOf({0.3, 0.4, 0.2});
  EXPECT_DOUBLE_EQ(up.lifted, 0.2);
  EXPECT_DOUBLE_EQ(up.lowered, 0.0);
  EXPECT_DOUBLE_EQ(up.horizontal, 0.5);
  const Travel down = TravelOf({0.0, 0.0, -0.1});
  EXPECT_DOUBLE_EQ(down.lowered, 0.1);
  EXPECT_DOUBLE_EQ(down.lifted, 0.0);
}

TEST(WorkEq4, ByHand) {
  // F = 20 N lifting 0.1 m, carrying 0.9 m, lowering 0.4 m, K = 6, n = 2:
  // (20*0.1 + 20*0.9/9 + 20*0.4/2) * 6 * 2 = (2 + 2 + 4) * 12 = 96 J.
  EXPECT_DOUBLE_EQ(WorkEq4(20.0, {0.1, 0.9, 0.4}, 6.0, 2.0), 96.0);
  EXPECT_DOUBLE_EQ(WorkEq4(0.0, {1, 1, 1}, 6.0), 0.0);
}

TEST(FatigueCoefficient, Eq6InSI) {
  const FatigueParams p;
  EXPECT_DOUBLE_EQ(p.a_max, 1600.0 * 4184.0);  // 1600 kcal
  EXPECT_DOUBLE_EQ(FatigueCoefficient(0.0, p.a_max), 1.0);
  EXPECT_DOUBLE_EQ(FatigueCoefficient(0.25 * p.a_max, p.a_max), 0.75);
  EXPECT_DOUBLE_EQ(FatigueCoefficient(p.a_max, p.a_max), 0.0);
  EXPECT_DOUBLE_EQ(FatigueCoefficient(2.0 * p.a_max, p.a_max),
                   0.0);  // held past exhaustion
}

TEST(IsExhausted, AtTheFloor) {
  EXPECT_FALSE(IsExhausted(0.06, 0.05));
  EXPECT_TRUE(IsExhausted(0.05, 0.05));
  EXPECT_TRUE(IsExhausted(0.0, 0.05));
}

}  // namespace
}  // namespace vahf::human
