// The part's rests (sim/rest_watch.h). The rule alone, decision by decision:
// a part held in contact counts one rest of the decisions' span; nearing or
// leaving its target faster than rest_speed, or out of contact at either end
// of an interval, it does not rest; a rest shorter than rest_time is not counted; a rest
// the trial's end cuts short is. Then trials: a block dropped onto a table rests there
// from the first decision after it lands to the last (its fall's time is sqrt(2 h / g)),
// the same rest on Simbody's integrator and on CVODE and at two accuracies (the rule
// reads only the decision instants); a block sliding down an incline faster than
// rest_speed never rests.
#include "vahf/sim/rest_watch.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial.h"

namespace vahf::sim {
namespace {

using Eigen::Vector3d;
using ::testing::HasSubstr;

constexpr double kG = 9.80665;

// The default simulation parameters: decisions 0.1 s apart, rest_speed
// 1 mm/s, rest_time 0.1 s.
scene::SimulationParams Defaults() { return {}; }

// Feeds decisions 0..n-1 with the part at distance(i) from its target
// (straight above it) and in contact in_contact(i), then closes; the rests
// ended on the way, in order.
template <class Distance, class Contact>
std::vector<Rest> Watch(RestWatch& w, int n, const Distance& distance,
                        const Contact& in_contact, const scene::SimulationParams& sim) {
  std::vector<Rest> out;
  for (int i = 0; i < n; ++i) {
    const double d = distance(i);
    if (auto r = w.Observe(i, Vector3d(0, 0, d), d, in_contact(i), sim))
      out.push_back(*r);
  }
  if (auto r = w.Close(sim)) out.push_back(*r);
  return out;
}

TEST(RestWatch, APartHeldInContactRestsOnceForTheSpanOfItsDecisions) {
  // Free until decision 3, then held in contact 0.2 m from the target,
  // creeping in 0.05 mm an interval (0.5 mm/s), until decision 9; free again
  // after.
  const auto distance = [](int i) {
    return i < 3 ? 0.5 - 0.1 * i : 0.2 - 5e-5 * (i - 3);
  };
  const auto contact = [](int i) { return i >= 3 && i <= 9; };
  RestWatch w;
  const std::vector<Rest> rests = Watch(w, 14, distance, contact, Defaults());
  ASSERT_EQ(rests.size(), 1u);
  EXPECT_DOUBLE_EQ(rests[0].start, 0.3);
  EXPECT_DOUBLE_EQ(rests[0].duration, 0.6);      // six intervals, 3 to 9
  EXPECT_DOUBLE_EQ(rests[0].position.z(), 0.2);  // T at its start
  EXPECT_DOUBLE_EQ(rests[0].distance, 0.2);
  EXPECT_THAT(rests[0].Detail(), HasSubstr("0.6 s from t = 0.3 s at T = (0, 0, 0.2) m"));
  EXPECT_EQ(w.summary().count, 1);
  EXPECT_DOUBLE_EQ(w.summary().total_time, 0.6);
  EXPECT_DOUBLE_EQ(w.summary().longest, 0.6);
}

TEST(RestWatch, APartMovingFasterThanRestSpeedDoesNotRest) {
  // In contact throughout, nearing or leaving the target at 1.01 mm/s: never
  // resting; at 0.99 mm/s: one rest of the whole trial.
  for (const double speed : {1.01e-3, 0.99e-3, -1.01e-3, -0.99e-3}) {
    const auto distance = [&](int i) { return 0.2 - speed * 0.1 * i; };
    RestWatch w;
    const std::vector<Rest> rests = Watch(
        w, 20, distance, [](int) { return true; }, Defaults());
    const bool slow = std::abs(speed) < 1e-3;
    EXPECT_EQ(rests.size(), slow ? 1u : 0u) << speed;
    EXPECT_EQ(w.summary().count, slow ? 1 : 0) << speed;
    if (!rests.empty()) {
      EXPECT_DOUBLE_EQ(rests[0].duration, 1.9);
    }
  }
}

TEST(RestWatch, ContactLostAtEitherEndOfAnIntervalEndsTheRest) {
  // Still throughout; out of contact at decision 5 only: rests 0-4 and 6-9
  // are not joined, the intervals (4, 5] and (5, 6] rest on no contact.
  RestWatch w;
  const std::vector<Rest> rests = Watch(
      w, 10, [](int) { return 0.2; }, [](int i) { return i != 5; }, Defaults());
  ASSERT_EQ(rests.size(), 2u);
  EXPECT_DOUBLE_EQ(rests[0].start, 0.0);
  EXPECT_DOUBLE_EQ(rests[0].duration, 0.4);
  EXPECT_DOUBLE_EQ(rests[1].start, 0.6);
  EXPECT_DOUBLE_EQ(rests[1].duration, 0.3);
  EXPECT_EQ(w.summary().count, 2);
  EXPECT_DOUBLE_EQ(w.summary().total_time, 0.7);
  EXPECT_DOUBLE_EQ(w.summary().longest, 0.4);
}

TEST(RestWatch, ARestShorterThanRestTimeIsNotCounted) {
  // Still in contact over decisions 2-4 (0.2 s), then going in at 1 cm/s; at
  // rest_time 0.25 s it is not counted, at 0.2 s it is (a rest's duration
  // is whole intervals, so the threshold is met exactly).
  const auto distance = [](int i) { return i <= 4 ? 0.2 : 0.2 - 1e-3 * (i - 4); };
  for (const double rest_time : {0.25, 0.2}) {
    scene::SimulationParams sim = Defaults();
    sim.rest_time = rest_time;
    RestWatch w;
    const std::vector<Rest> rests = Watch(
        w, 10, distance, [](int i) { return i >= 2; }, sim);
    EXPECT_EQ(rests.size(), rest_time > 0.2 ? 0u : 1u) << rest_time;
    EXPECT_EQ(w.summary().count, rest_time > 0.2 ? 0 : 1) << rest_time;
  }
}

TEST(RestWatch, TheOpenRestGrowsByAnIntervalPerDecisionAndEndsWithIt) {
  const scene::SimulationParams sim = Defaults();
  RestWatch w;
  const auto at = [&](int i, double d, bool contact) {
    w.Observe(i, Vector3d(0, 0, d), d, contact, sim);
    return w.OpenRest(sim.decision_interval);
  };
  EXPECT_EQ(at(0, 0.2, true), 0.0);
  EXPECT_DOUBLE_EQ(at(1, 0.2, true), 0.1);
  EXPECT_DOUBLE_EQ(at(2, 0.2, true), 0.2);
  EXPECT_DOUBLE_EQ(at(3, 0.2, true), 0.3);
  EXPECT_EQ(at(4, 0.21, true), 0.0);  // 1 cm in 0.1 s: moving, the rest ended
  EXPECT_EQ(w.summary().count, 1);
  EXPECT_EQ(w.summary().withdrawals, 0);
  w.Withdrew();
  EXPECT_EQ(w.summary().withdrawals, 1);
}

TEST(RestWatch, ARestSpeedOfZeroCountsNoRest) {
  scene::SimulationParams sim = Defaults();
  sim.rest_speed = 0;
  RestWatch w;
  EXPECT_TRUE(Watch(
                  w, 10, [](int) { return 0.2; }, [](int) { return true; }, sim)
                  .empty());
}

// Trials. A 4 cm aluminium block dropped from `height` above a table's top
// with no operator; decisions every 0.1 s to 1.0 s.
scene::Scene DroppedBlock(double height, const std::string& integrator, double accuracy,
                          double rest_time) {
  nlohmann::json table = {{"name", "table"},
                          {"role", "base"},
                          {"geometry", {{"type", "box"}, {"size", {0.4, 0.4, 0.05}}}},
                          {"density", 2700},
                          {"friction", 0.2},
                          {"pose", {{"position", {0.0, 0.0, 0.875}}}}};
  nlohmann::json block = {{"name", "block"},
                          {"role", "assembling"},
                          {"geometry", {{"type", "box"}, {"size", {0.04, 0.04, 0.04}}}},
                          {"density", 2700},
                          {"friction", 0.2},
                          {"pose", {{"position", {0.0, 0.0, 0.92 + height}}}},
                          {"target", {{"position", {0.0, 0.0, 1.5}}}}};
  const nlohmann::json doc = {
      {"format", "vahf-scene/1"},
      {"name", "drop"},
      {"operator",
       {{"height", 1.75},
        {"arm_length", 0.74},
        {"position", {0.0, -0.35}},
        {"facing_deg", 90}}},
      {"parts", {table, block}},
      {"sequence", {"block"}},
      {"parameters",
       {{"guidance", {{"mode", "none"}}},
        {"visibility", {{"mode", "off"}}},
        {"contact", {{"stiffness", 1e8}, {"shell_spacing", 0.005}, {"dissipation", 50}}},
        {"simulation",
         {{"time_limit", 1.05},
          {"decision_interval", 0.1},
          {"integrator", integrator},
          {"accuracy", accuracy},
          {"rest_time", rest_time}}}}}};
  return scene::ParseScene(doc, "drop.json");
}

TEST(RestWatch, ABlockDroppedOnATableRestsFromItsLandingToTheEnd) {
  // It lands after sqrt(2 h / g) = 0.101 s from 5 cm: out of contact at
  // 0.1 s, settled by 0.2 s, resting to the last decision at 1.0 s.
  const double height = 0.05;
  ASSERT_GT(std::sqrt(2 * height / kG), 0.1);
  ASSERT_LT(std::sqrt(2 * height / kG), 0.15);
  for (const char* integrator : {"RungeKuttaMerson", "CVODE"}) {
    for (const double accuracy : {1e-4, 1e-6}) {
      SCOPED_TRACE(std::string(integrator) + " " + std::to_string(accuracy));
      const TrialResult r =
          RunTrial(DroppedBlock(height, integrator, accuracy, 0.1), {1, 0});
      ASSERT_EQ(r.status, Status::kTimeout) << r.detail;
      EXPECT_EQ(r.rests.count, 1);
      EXPECT_DOUBLE_EQ(r.rests.total_time, 0.8);
      EXPECT_DOUBLE_EQ(r.rests.longest, 0.8);
      const WarningEntry& w = r.warnings.at(WarningKind::kRest);
      EXPECT_EQ(w.count, 1);
      EXPECT_DOUBLE_EQ(w.first_time, 0.2);
      EXPECT_THAT(w.detail, HasSubstr("0.8 s from t = 0.2 s at T = ("));
      EXPECT_THAT(w.detail, HasSubstr("m from the target"));
      EXPECT_THAT(r.BriefReport(), HasSubstr("rests (simulation/rest_speed, rest_time): "
                                             "1, 0.8 s in all, the longest 0.8 s"));
    }
  }
  // Longer than the rest, rest_time counts none.
  const TrialResult r = RunTrial(DroppedBlock(height, "CVODE", 1e-4, 0.85), {1, 0});
  EXPECT_EQ(r.rests.count, 0);
  EXPECT_EQ(r.warnings.at(WarningKind::kRest).count, 0);
}

TEST(RestWatch, ABlockSlidingDownAnInclineNeverRests) {
  // tan 20 deg = 0.364 > mu = 0.2: it slides at a = g (sin - mu cos) =
  // 1.51 m/s^2, in contact throughout, away from a target up the slope's
  // side at 0.59 of its speed: 1 mm/s within 2 ms.
  const double theta = 20.0, t = theta * M_PI / 180.0;
  const Vector3d n(0, -std::sin(t), std::cos(t));
  const Vector3d c = Vector3d(0, 0, 0.5) + (0.025 + 0.02) * n;
  const auto box = [&](const char* name, const char* role, nlohmann::json size,
                       const Vector3d& p) {
    return nlohmann::json{
        {"name", name},
        {"role", role},
        {"geometry", {{"type", "box"}, {"size", size}}},
        {"density", 2700},
        {"friction", 0.2},
        {"pose",
         {{"position", {p.x(), p.y(), p.z()}}, {"rotation_xyz_deg", {theta, 0, 0}}}}};
  };
  nlohmann::json block = box("block", "assembling", {0.04, 0.04, 0.04}, c);
  block["target"] = {{"position", {0.0, 0.4, 2.0}}};
  const nlohmann::json doc = {
      {"format", "vahf-scene/1"},
      {"name", "incline"},
      {"operator",
       {{"height", 1.75},
        {"arm_length", 0.74},
        {"position", {0.0, -0.35}},
        {"facing_deg", 90}}},
      {"parts", {box("slab", "base", {0.6, 1.2, 0.05}, Vector3d(0, 0, 0.5)), block}},
      {"sequence", {"block"}},
      {"parameters",
       {{"guidance", {{"mode", "none"}}},
        {"visibility", {{"mode", "off"}}},
        {"contact", {{"stiffness", 1e8}, {"shell_spacing", 0.005}, {"dissipation", 20}}},
        {"simulation", {{"time_limit", 0.5}, {"decision_interval", 0.05}}}}}};
  const TrialResult r = RunTrial(scene::ParseScene(doc, "incline.json"), {1, 0});
  ASSERT_EQ(r.status, Status::kTimeout) << r.detail;
  for (const TraceRow& row : r.trace)  // placed touching: pressed from the first step
    if (row.time > 0) {
      EXPECT_GT(row.contact_force.norm(), 0) << row.time;
    }
  EXPECT_EQ(r.rests.count, 0);
  EXPECT_EQ(r.warnings.at(WarningKind::kRest).count, 0) << r.warnings.Summary();
}

}  // namespace
}  // namespace vahf::sim
