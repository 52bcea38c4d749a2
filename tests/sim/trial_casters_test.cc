// The trials of one trial model share its visibility casters
// (TrialModel::casters, docs/design.md decision 13): against trials that
// each had a model, and so a caster, of their own, as every trial did before
// the pool, trials that borrow the shared model's casters in turn on one
// thread, and at once on two, give the same trace bytes (V at every decision)
// and the same count of rays; the model builds one caster for any number of
// trials on one thread and at most two on two threads.
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trace_csv.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim {
namespace {

constexpr int kTrials = 4;

// The shell peg sinking into the bore, which hides it (V from 1 down to about
// 0.6: tests/sim/trial_test.cc), on a coarse grid and with decisions every
// 20 ms, so that a trial casts V often and quickly.
scene::Scene HiddenPeg() {
  scene::Scene s = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                    "/experiments/scenes/peg_in_hole_shell.json");
  s.params.visibility.mode = "raycast";
  s.params.visibility.grid = 32;
  s.params.simulation.decision_interval = 0.02;
  return s;
}

TrialResult RunSeed(const TrialModel& model, int k) {
  return RunTrial(model, {1, static_cast<std::uint64_t>(k)});
}

TEST(TrialCasters, TrialsOfOneModelShareItsCastersWithTheSameBits) {
  const scene::Scene s = HiddenPeg();
  // Each trial with a model and a caster of its own.
  std::vector<TrialResult> own;
  for (int k = 0; k < kTrials; ++k) {
    const auto model = BuildTrialModel(s, 0);
    own.push_back(RunSeed(*model, k));
    EXPECT_EQ(model->casters->casters_built(), 1u);
  }
  ASSERT_GT(own[0].counters.rays_cast, 0);
  ASSERT_LT(own[0].trace.back().factors.V, 0.9);  // the bore hid part of it

  // One model, its trials in turn on one thread: one caster for all.
  const auto shared = BuildTrialModel(s, 0);
  ASSERT_TRUE(shared->casters);
  EXPECT_EQ(shared->casters->casters_built(), 0u);  // built on first need
  for (int k = 0; k < kTrials; ++k) {
    const TrialResult r = RunSeed(*shared, k);
    EXPECT_EQ(TraceCsv(r), TraceCsv(own[k])) << "trial " << k;
    EXPECT_EQ(r.counters.rays_cast, own[k].counters.rays_cast) << "trial " << k;
  }
  EXPECT_EQ(shared->casters->casters_built(), 1u);

  // Another model, its trials on two threads at once: a caster per thread at most.
  const auto two = BuildTrialModel(s, 0);
  std::vector<std::unique_ptr<TrialResult>> results(kTrials);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      for (int k = t; k < kTrials; k += 2)
        results[k] = std::make_unique<TrialResult>(RunSeed(*two, k));
    });
  for (std::thread& t : threads) t.join();
  EXPECT_GE(two->casters->casters_built(), 1u);
  EXPECT_LE(two->casters->casters_built(), 2u);
  for (int k = 0; k < kTrials; ++k) {
    EXPECT_EQ(TraceCsv(*results[k]), TraceCsv(own[k])) << "trial " << k;
    EXPECT_EQ(results[k]->counters.rays_cast, own[k].counters.rays_cast) << "trial " << k;
  }
}

TEST(TrialCasters, NoCasterWithoutRaysToCast) {
  // V given as a constant, or nothing fixed to hide the part: no pool at all.
  scene::Scene s = HiddenPeg();
  s.params.visibility.mode = "constant";
  EXPECT_FALSE(BuildTrialModel(s, 0)->casters);
  scene::Scene free_move = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                            "/experiments/scenes/free_move.json");
  free_move.params.visibility.mode = "raycast";
  EXPECT_FALSE(BuildTrialModel(free_move, 0)->casters);
}

}  // namespace
}  // namespace vahf::sim
