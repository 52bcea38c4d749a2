// Tests of the checks that end a trial at a decision (sim/outcome.h): each
// rule fires exactly past its threshold, in its order of precedence, and its
// detail names the measured value and the threshold.
#include "vahf/sim/outcome.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace vahf::sim {
namespace {

using ::testing::HasSubstr;

contact::RigidMotion Moving(const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
  contact::RigidMotion m;
  m.pose.translation() = Eigen::Vector3d(0.1, 0.2, 0.3);
  m.velocity = v;
  m.angular_velocity = w;
  return m;
}

TEST(CheckState, AFiniteSlowStateIsUsable) {
  scene::SimulationParams sim;
  EXPECT_FALSE(CheckState(Moving({1, 0, 0}, {0, 0, 1}), 0.1, sim, "decision", 3, 0.3));
}

TEST(CheckState, EveryNonFiniteComponentIsANumericalFailure) {
  scene::SimulationParams sim;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  contact::RigidMotion m = Moving({0, 0, 0}, {0, 0, 0});
  m.pose.translation().y() = nan;
  std::optional<Ending> e = CheckState(m, 0.1, sim, "decision", 7, 0.7);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->status, Status::kNumericalFailure);
  EXPECT_EQ(e->detail, "non-finite state at decision 7 (t = 0.7 s)");
  EXPECT_TRUE(CheckState(Moving({0, inf, 0}, {0, 0, 0}), 0.1, sim, "decision", 1, 0.1));
  EXPECT_TRUE(CheckState(Moving({0, 0, 0}, {0, 0, nan}), 0.1, sim, "decision", 1, 0.1));
  m = Moving({0, 0, 0}, {0, 0, 0});
  m.pose.linear()(1, 2) = nan;
  EXPECT_TRUE(CheckState(m, 0.1, sim, "decision", 1, 0.1));
}

TEST(CheckState, DivergenceBoundsTheFastestPointOfTheBoundingSphere) {
  scene::SimulationParams sim;
  sim.divergence_speed = 20.0;
  // 12 m/s + 100 rad/s * 0.08 m = 20 m/s: at the threshold, not past it.
  EXPECT_FALSE(
      CheckState(Moving({12, 0, 0}, {0, 100, 0}), 0.08, sim, "decision", 2, 0.2));
  std::optional<Ending> e =
      CheckState(Moving({12, 0, 0}, {0, 100, 0}), 0.081, sim, "decision", 2, 0.2);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->status, Status::kNumericalFailure);
  EXPECT_THAT(e->detail, HasSubstr("up to 20.1 m/s > divergence_speed 20 m/s"));
  EXPECT_THAT(e->detail, HasSubstr("decision 2 (t = 0.2 s, position 0.1 0.2 0.3 m)"));
}

DecisionFacts Facts() {
  DecisionFacts f;
  f.time = 5.0;
  f.psi = 0.8;
  f.work = 1000;
  f.shoulder_distance = 0.5;
  f.reach_limit = 0.7;
  f.distance = 0.01;
  return f;
}

TEST(CheckOperator, NothingEndsAnOrdinaryDecision) {
  ProgressWatch w;
  w.Observe(true, 0.0, 0.2, false, 1e-4);
  EXPECT_FALSE(CheckOperator(Facts(), {}, {}, w));
}

TEST(CheckOperator, ExhaustedAtTheFloorThenUnreachableBeyondD3) {
  human::FatigueParams fatigue;
  fatigue.psi_floor = 0.05;
  ProgressWatch w;
  DecisionFacts f = Facts();
  f.psi = 0.05;
  f.shoulder_distance = 0.9;  // also out of reach: exhaustion comes first
  std::optional<Ending> e = CheckOperator(f, fatigue, {}, w);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->status, Status::kExhausted);
  EXPECT_EQ(e->detail, "Psi_c = 0.0500 <= floor 0.05 at t = 5 s (A = 1000 J)");
  f.psi = 0.0501;
  e = CheckOperator(f, fatigue, {}, w);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->status, Status::kUnreachable);
  EXPECT_EQ(e->detail, "shoulder distance 0.9000 m > D3 = 0.7000 m at t = 5 s");
  f.shoulder_distance = 0.7;  // at D3: still reachable
  EXPECT_FALSE(CheckOperator(f, fatigue, {}, w));
}

TEST(CheckOperator, WithoutAnOperatorNeitherFatigueNorReachEndsATrial) {
  ProgressWatch w;
  DecisionFacts f = Facts();
  f.operator_acts = false;
  f.psi = 0.0;
  f.shoulder_distance = 5.0;
  EXPECT_FALSE(CheckOperator(f, {}, {}, w));
}

TEST(CheckOperator, JammedAfterJamTimeInContactWithoutProgress) {
  scene::SimulationParams sim;
  sim.jam_time = 2.0;
  sim.jam_progress = 1e-4;
  ProgressWatch w;
  w.Observe(true, 0.0, 0.0100, true, sim.jam_progress);
  // 0.5e-4 m closer is not progress; out of contact is.
  w.Observe(false, 1.0, 0.00995, true, sim.jam_progress);
  EXPECT_EQ(w.last_progress_time(), 0.0);
  DecisionFacts f = Facts();
  f.in_contact = true;
  f.time = 1.9;
  EXPECT_FALSE(CheckOperator(f, {}, sim, w));
  f.time = 2.0;
  std::optional<Ending> e = CheckOperator(f, {}, sim, w);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->status, Status::kJammed);
  EXPECT_EQ(e->detail,
            "in contact without 0.0001 m of progress since t = 0 s; 0.010000 m from the "
            "target");
  f.in_contact = false;  // out of contact, no jam whatever the time
  EXPECT_FALSE(CheckOperator(f, {}, sim, w));
}

TEST(ProgressWatch, ProgressIsAJamProgressApproachOrLeavingContact) {
  ProgressWatch w;
  w.Observe(true, 0.0, 0.0100, true, 1e-4);
  w.Observe(false, 0.5, 0.00985, true, 1e-4);  // 1.5e-4 closer: progress
  EXPECT_EQ(w.last_progress_time(), 0.5);
  w.Observe(false, 1.0, 0.0200, false, 1e-4);  // out of contact: progress
  EXPECT_EQ(w.last_progress_time(), 1.0);
  w.Observe(false, 1.5, 0.0300, true, 1e-4);  // back in contact, farther: none
  EXPECT_EQ(w.last_progress_time(), 1.0);
  w.Observe(false, 1.7, 0.0098, true, 1e-4);  // 0.5e-4 closer than the best: none
  EXPECT_EQ(w.last_progress_time(), 1.0);
  w.Observe(false, 2.0, 0.0097, true, 1e-4);  // 1.5e-4 closer than the best 0.00985
  EXPECT_EQ(w.last_progress_time(), 2.0);
}

TEST(ProgressWatch, AfterAWithdrawalOnlyApproachingBeyondTheBestIsProgress) {
  ProgressWatch w;
  w.Observe(true, 0.0, 0.0100, true, 1e-4);
  w.Withdrew();
  w.Observe(false, 0.1, 0.0150, false, 1e-4);  // pulled out of contact: none
  EXPECT_EQ(w.last_progress_time(), 0.0);
  w.Observe(false, 0.2, 0.0120, false, 1e-4);  // coming back, still out: none
  EXPECT_EQ(w.last_progress_time(), 0.0);
  w.Observe(false, 0.3, 0.0100, true, 1e-4);  // stopped where it was: none
  EXPECT_EQ(w.last_progress_time(), 0.0);
  w.Observe(false, 0.4, 0.0098, true, 1e-4);  // 2e-4 deeper than the best: progress
  EXPECT_EQ(w.last_progress_time(), 0.4);
  w.Observe(false, 0.5, 0.0200, false, 1e-4);  // out of contact again: progress
  EXPECT_EQ(w.last_progress_time(), 0.5);
}

}  // namespace
}  // namespace vahf::sim
