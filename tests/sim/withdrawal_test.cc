// The operator's response to a part that stops (guidance/stall_time,
// guidance/withdraw_distance; docs/physics.md, "When the part stops"): an
// operator presses a block onto a table towards a target inside it, which it
// can never reach. The block rests on the table; each time it has rested
// stall_time the operator pulls it withdraw_distance back up, holding the
// target's orientation, and guides it down again, where it stops again. It
// gets no deeper, so the jam rule ends it after jam_time: the withdrawals do
// not count as progress. With stall_time 0 the operator never responds.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial.h"

namespace vahf::sim {
namespace {

// A 4 cm aluminium block resting on a table whose top is at z = 0.9 m, its
// target 5 cm inside the table; decisions every 0.1 s.
scene::Scene PressedBlock(double stall_time) {
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
                          {"pose", {{"position", {0.0, 0.0, 0.92}}}},
                          {"target", {{"position", {0.0, 0.0, 0.87}}}}};
  const nlohmann::json doc = {
      {"format", "vahf-scene/1"},
      {"name", "pressed"},
      {"operator",
       {{"height", 1.75},
        {"arm_length", 0.74},
        {"position", {0.0, -0.35}},
        {"facing_deg", 90}}},
      {"parts", {table, block}},
      {"sequence", {"block"}},
      {"parameters",
       {{"guidance", {{"stall_time", stall_time}, {"withdraw_distance", 0.005}}},
        {"visibility", {{"mode", "off"}}},
        {"contact", {{"stiffness", 1e8}, {"shell_spacing", 0.005}, {"dissipation", 50}}},
        {"simulation",
         {{"time_limit", 4.0},
          {"decision_interval", 0.1},
          {"jam_time", 2.0},
          {"integrator", "CVODE"},
          {"accuracy", 1e-5}}}}}};
  return scene::ParseScene(doc, "pressed.json");
}

TEST(Withdrawal, AStoppedPartIsPulledBackAndAPartThatStopsAgainIsJammed) {
  TrialOptions options;
  options.record_trace = true;
  const TrialResult r = RunTrial(PressedBlock(0.24), {1, 0}, options);
  ASSERT_EQ(r.status, Status::kJammed) << r.detail;
  EXPECT_LT(r.end_time, 3.0);  // by the jam rule, not the time limit
  EXPECT_GE(r.rests.withdrawals, 3);
  // Resting on the table, the block's centre is 2 cm above its top; at the
  // decision after a withdrawal it is higher by most of withdraw_distance.
  int lifted = 0;
  for (std::size_t k = 1; k < r.trace.size(); ++k)
    if (r.trace[k].position.z() > 0.92 + 0.002) ++lifted;
  EXPECT_GE(lifted, 3);
  EXPECT_LE(lifted, r.rests.withdrawals);

  const TrialResult never = RunTrial(PressedBlock(0.0), {1, 0}, options);
  ASSERT_EQ(never.status, Status::kJammed) << never.detail;
  EXPECT_EQ(never.rests.withdrawals, 0);
  for (const TraceRow& row : never.trace)
    EXPECT_LT(row.position.z(), 0.92 + 0.002) << row.time;
}

}  // namespace
}  // namespace vahf::sim
