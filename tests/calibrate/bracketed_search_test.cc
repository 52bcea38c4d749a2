// The one-parameter search of the golden_section solver (bracketed_search.h): it must
// find the minimum of a smooth cost, of a piecewise-constant one (the shape
// of a success rate over a few cycles on common random numbers), stop at a
// bound when the cost still falls there, reuse a bracket that still holds,
// and pass an exception of the cost through untouched.
#include "vahf/calibrate/bracketed_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "vahf/core/error.h"

namespace vahf::calibrate {
namespace {

TEST(BracketedSearch, FindsASmoothMinimumToTheTolerance) {
  int calls = 0;
  const auto cost = [&](double x) {
    ++calls;
    return std::pow(std::log(x / 37.0), 2);  // minimum at 37
  };
  const BracketedSearch s = MinimizeBracketed(cost, 1, 400, 5, 0.01, 50);
  EXPECT_TRUE(s.converged) << s.log;
  EXPECT_FALSE(s.at_bound);
  EXPECT_NEAR(s.estimate, 37.0, 37.0 * 0.01) << s.log;
  EXPECT_LE(s.bracket[0], 37.0);
  EXPECT_GE(s.bracket[2], 37.0);
  // Each iterate costs one evaluation: far fewer than a grid at 1 %.
  EXPECT_LT(calls, 30) << s.log;
}

TEST(BracketedSearch, CrossesPlateausOfAStepFunction) {
  // A success rate of 6 cycles, each failing below its own threshold,
  // against a target of 4/6: the cost is 0 on [thresholds 2, 3) only.
  const double thresholds[6] = {100, 180, 260, 340, 420, 500};
  const auto cost = [&](double a_max) {
    int ok = 0;
    for (double t : thresholds) ok += a_max >= t;
    const double r = ok / 6.0 - 4.0 / 6.0;
    return r * r;
  };
  // Starting on a plateau (cost equal on both first points), the walk must
  // still find strictly higher costs on each side.
  const BracketedSearch s = MinimizeBracketed(cost, 10, 10000, 3000, 0.02, 50);
  EXPECT_FALSE(s.at_bound) << s.log;
  EXPECT_GE(s.estimate, 340.0) << s.log;
  EXPECT_LT(s.estimate, 420.0) << s.log;
  EXPECT_DOUBLE_EQ(s.cost, 0.0);
}

TEST(BracketedSearch, StopsAtABoundWhereTheCostStillFalls) {
  const auto cost = [](double x) { return 1.0 / x; };
  const BracketedSearch s = MinimizeBracketed(cost, 1, 100, 2, 0.01, 50);
  EXPECT_TRUE(s.at_bound) << s.log;
  EXPECT_FALSE(s.converged);
  EXPECT_DOUBLE_EQ(s.estimate, 100.0);
}

TEST(BracketedSearch, SearchesLinearlyWhenTheRangeIsNotPositive) {
  const auto cost = [](double x) { return (x + 0.3) * (x + 0.3); };
  const BracketedSearch s = MinimizeBracketed(cost, -1, 1, 0.5, 0.01, 60);
  EXPECT_TRUE(s.converged) << s.log;
  EXPECT_NEAR(s.estimate, -0.3, 0.01) << s.log;
}

TEST(BracketedSearch, ReusesABracketThatStillHolds) {
  int calls = 0;
  const auto cost = [&](double x) {
    ++calls;
    return std::pow(std::log(x / 37.0), 2);
  };
  const BracketedSearch s =
      MinimizeBracketed(cost, 1, 400, 30, 0.01, 50, {{20.0, 30.0, 80.0}});
  EXPECT_NE(s.log.find("bracket from the last round"), std::string::npos) << s.log;
  EXPECT_EQ(s.log.find("walk:"), std::string::npos) << s.log;
  EXPECT_NEAR(s.estimate, 37.0, 0.4);
  // A hint that no longer brackets is dropped for a walk.
  const BracketedSearch t =
      MinimizeBracketed(cost, 1, 400, 30, 0.01, 50, {{1.0, 2.0, 3.0}});
  EXPECT_NE(t.log.find("walk:"), std::string::npos) << t.log;
  EXPECT_NEAR(t.estimate, 37.0, 0.4);
}

TEST(BracketedSearch, AnErrorOfTheCostPassesThrough) {
  const auto cost = [](double x) {
    if (x > 10 && x < 20) throw std::runtime_error("interrupted");
    return std::pow(std::log(x / 15.0), 2);
  };
  EXPECT_THROW(MinimizeBracketed(cost, 1, 400, 5, 0.001, 50), std::runtime_error);
}

TEST(BracketedSearch, ANonFiniteCostCountsAsTheWorst) {
  // No sample below 8 (an objective that cannot be computed there).
  const auto cost = [](double x) { return x < 8 ? std::nan("") : std::pow(x - 12, 2); };
  const BracketedSearch s = MinimizeBracketed(cost, 1, 100, 2, 0.01, 60);
  EXPECT_TRUE(s.converged) << s.log;
  EXPECT_NEAR(s.estimate, 12.0, 0.15) << s.log;
}

TEST(BracketedSearch, RefusesAStartOutsideTheBounds) {
  EXPECT_THROW(MinimizeBracketed([](double) { return 0.0; }, 1, 2, 3, 0.01, 5),
               ComputationError);
}

// The profile interval (ProfileBounds): of a whitened quadratic cost, 1/2
// ((x - 37) / 2)^2, it is the normal interval 37 +- 1.96 * 2 to its
// tolerance; of a step function, the steps within the rise; where the cost
// stays within the rise up to a bound, that side is open.
TEST(ProfileInterval, OfAQuadraticCostIsTheNormalInterval) {
  const auto cost = [](double x) { return 0.5 * std::pow((x - 37.0) / 2.0, 2); };
  const double rise = 0.5 * 3.841458820694124;
  const ProfileInterval p = ProfileBounds(cost, 1, 400, 37, 0, rise, 0.05, 0.001);
  EXPECT_FALSE(p.open_lower);
  EXPECT_FALSE(p.open_upper);
  EXPECT_NEAR(p.lower, 37 - 1.959964 * 2, 37 * 0.001) << p.log;
  EXPECT_NEAR(p.upper, 37 + 1.959964 * 2, 37 * 0.001) << p.log;
  EXPECT_LT(p.evaluations, 40);
  // Linear search where the range is not positive: the same interval.
  const auto shifted = [&](double x) { return cost(x + 37.0); };
  const ProfileInterval q = ProfileBounds(shifted, -100, 100, 0, 0, rise, 0.05, 0.001);
  EXPECT_NEAR(q.lower, -1.959964 * 2, 0.01) << q.log;
  EXPECT_NEAR(q.upper, 1.959964 * 2, 0.01) << q.log;
}

TEST(ProfileInterval, OfAStepFunctionEndsAtItsSteps) {
  // 0 on [20, 30), 1 on [10, 20) and [30, 40), 5 elsewhere: within the rise
  // 1.92 of the minimum on [10, 40).
  const auto cost = [](double x) {
    return x >= 20 && x < 30 ? 0.0 : (x >= 10 && x < 40) ? 1.0 : 5.0;
  };
  const ProfileInterval p = ProfileBounds(cost, 1, 1000, 25, 0, 1.92, 0.05, 0.01);
  EXPECT_NEAR(p.lower, 10, 0.2) << p.log;
  EXPECT_NEAR(p.upper, 40, 0.5) << p.log;
}

TEST(ProfileInterval, IsOpenWhereTheCostStaysWithinTheRiseToABound) {
  // Flat above 30 (a parameter the data stop seeing), rising below.
  const auto cost = [](double x) {
    return x >= 30 ? 0.0 : std::pow(std::log(30 / x), 2) * 50;
  };
  const ProfileInterval p = ProfileBounds(cost, 1, 400, 40, 0, 1.92, 0.05, 0.01);
  EXPECT_TRUE(p.open_upper);
  EXPECT_EQ(p.upper, 400);
  EXPECT_FALSE(p.open_lower);
  EXPECT_NEAR(p.lower, 30 * std::exp(-std::sqrt(1.92 / 50)), 0.3) << p.log;
  // A non-finite cost counts as past the rise.
  const auto broken = [](double x) { return x < 20 ? std::nan("") : 0.0; };
  const ProfileInterval b = ProfileBounds(broken, 1, 400, 40, 0, 1.92, 0.05, 0.01);
  EXPECT_NEAR(b.lower, 20, 0.3) << b.log;
  EXPECT_THROW(ProfileBounds(cost, 1, 400, 500, 0, 1.92, 0.05, 0.01), ComputationError);
}

}  // namespace
}  // namespace vahf::calibrate
