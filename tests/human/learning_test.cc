// Learning over repetitions: De Jong's curve and the gain that shortens a
// free reach by it (human/learning.h).
#include "vahf/human/learning.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vahf::human {
namespace {

TEST(Learning, NoneLeavesEveryRepetitionTheFirst) {
  LearningParams p;  // model "none"
  for (int n : {1, 2, 10, 1000}) {
    EXPECT_EQ(PracticeTimeFactor(p, n), 1.0);
    EXPECT_EQ(PracticeGain(p, n), 1.0);
  }
}

TEST(Learning, PowerLawHalvesPerDoublingAtTheEightyPercentCurve) {
  LearningParams p;
  p.model = "power_law";
  p.exponent = -std::log2(0.8);  // Wright's 80 % curve
  EXPECT_EQ(PracticeTimeFactor(p, 1), 1.0);
  for (int n : {1, 2, 4, 8, 16})
    EXPECT_NEAR(PracticeTimeFactor(p, 2 * n) / PracticeTimeFactor(p, n), 0.8, 1e-14);
  // The floor is De Jong's only.
  p.floor = 0.5;
  EXPECT_NEAR(PracticeTimeFactor(p, 4), 0.64, 1e-14);
}

TEST(Learning, DeJongApproachesItsFloor) {
  LearningParams p;
  p.model = "de_jong";
  p.exponent = 0.5;
  p.floor = 0.25;
  EXPECT_EQ(PracticeTimeFactor(p, 1), 1.0);
  EXPECT_NEAR(PracticeTimeFactor(p, 4), 0.25 + 0.75 * 0.5, 1e-15);
  EXPECT_NEAR(PracticeTimeFactor(p, 1'000'000), 0.25 + 0.75e-3, 1e-15);
  for (int n = 1; n < 50; ++n)
    EXPECT_LT(PracticeTimeFactor(p, n + 1), PracticeTimeFactor(p, n));
}

TEST(Learning, TheGainIsTheTimeFactorToTheMinusTwo) {
  LearningParams p;
  p.model = "de_jong";
  p.exponent = 0.3;
  p.floor = 0.1;
  for (int n : {1, 3, 7, 20}) {
    const double l = PracticeTimeFactor(p, n);
    EXPECT_NEAR(PracticeGain(p, n) * l * l, 1.0, 1e-14);
  }
}

}  // namespace
}  // namespace vahf::human
