// The MoreauJean stepper in a trial (scene/steppers.def; sim/moreau_jean_stepper.cc):
// free fall at theta = 1/2 is exact; the resolved peg completes within its
// penetration bound, its completion time converging as the step is refined
// and the same bits on two runs and on two threads at once; a scene whose
// contact is not the exact revolved one is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/free_fall.h"
#include "vahf/core/error.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim {
namespace {

namespace settings = scene::stepper_settings;

scene::Scene Peg(double step) {
  scene::Scene s = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                    "/experiments/scenes/peg_in_hole.json");
  s.params.simulation.integrator = "MoreauJean";
  s.params.simulation.stepper_values.Upd(settings::moreau_jean_step) = step;
  return s;
}

TEST(MoreauJeanStepper, FreeFallAtThetaOneHalfIsExact) {
  const nlohmann::json doc = testing::FreeFallScene({{"time_limit", 0.5},
                                                     {"decision_interval", 0.05},
                                                     {"integrator", "MoreauJean"},
                                                     {"moreau_jean_step", 1e-3},
                                                     {"moreau_jean_theta", 0.5}});
  const TrialResult r = RunTrial(scene::ParseScene(doc, "fall.json"), {1, 0});
  ASSERT_EQ(r.status, Status::kTimeout) << r.detail;
  ASSERT_EQ(r.trace.size(), 10u);
  const double g = 9.80665;
  for (const TraceRow& row : r.trace) {
    // The trapezoidal rule on positions is exact for constant acceleration.
    EXPECT_NEAR(row.position.z(), 1.0 - 0.5 * g * row.time * row.time, 1e-12) << row.time;
    EXPECT_NEAR(row.velocity.z(), -g * row.time, 1e-12) << row.time;
  }
  EXPECT_EQ(r.counters.steps_taken, 500);
  EXPECT_EQ(r.integrator, "MoreauJean");
}

// Measured (release, seed 1): 0.147186, 0.135315 and 0.131440 s at steps of
// 5e-4, 2.5e-4 and 1.25e-4 s; at 1e-3 s the peg took another path (0.31 s).
TEST(MoreauJeanStepper, ThePegConvergesAsTheStepIsRefined) {
  double t[3];
  const double steps[3] = {5e-4, 2.5e-4, 1.25e-4};
  for (int k = 0; k < 3; ++k) {
    const TrialResult r = RunTrial(Peg(steps[k]), {1, 0});
    ASSERT_EQ(r.status, Status::kCompleted) << steps[k] << ": " << r.detail;
    EXPECT_EQ(r.warnings.at(WarningKind::kPenetrationBound).count, 0) << steps[k];
    EXPECT_EQ(r.warnings.at(WarningKind::kContactSolver).count, 0) << steps[k];
    t[k] = r.completion_time;
  }
  EXPECT_LT(std::abs(t[1] - t[2]), 0.5 * std::abs(t[0] - t[2]));
  EXPECT_NEAR(t[1], t[2], 0.03 * t[2]);
}

bool SameBits(const TrialResult& a, const TrialResult& b) {
  return a.status == b.status && a.completion_time == b.completion_time &&
         a.end_time == b.end_time && a.counters.steps_taken == b.counters.steps_taken &&
         a.trace.size() == b.trace.size() &&
         (a.trace.empty() || (a.trace.back().position == b.trace.back().position &&
                              a.trace.back().velocity == b.trace.back().velocity));
}

TEST(MoreauJeanStepper, TheSameBitsTwiceAndOnTwoThreadsAtOnce) {
  const scene::Scene s = Peg(5e-4);
  const TrialResult first = RunTrial(s, {2, 0});
  const TrialResult again = RunTrial(s, {2, 0});
  EXPECT_TRUE(SameBits(first, again));
  TrialResult on_thread[2];
  std::thread a([&] { on_thread[0] = RunTrial(s, {2, 0}); });
  std::thread b([&] { on_thread[1] = RunTrial(s, {2, 0}); });
  a.join();
  b.join();
  EXPECT_TRUE(SameBits(first, on_thread[0]));
  EXPECT_TRUE(SameBits(first, on_thread[1]));
}

TEST(MoreauJeanStepper, AContactOnSampledPointsIsRefusedByName) {
  scene::Scene s = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                    "/experiments/scenes/peg_in_hole_shell.json");
  s.params.simulation.integrator = "MoreauJean";
  try {
    BuildTrialModel(s, 0);
    FAIL() << "a shell contact was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/parameters/simulation/integrator");
    EXPECT_NE(std::string(e.rule()).find("contact/model \"resolving\""),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.rule()).find("\"shell\""), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vahf::sim
