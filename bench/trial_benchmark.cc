// Speed of one shell peg trial (experiments/scenes/peg_in_hole_shell.json, seed 1)
// at accuracy 1e-4 with RungeKuttaMerson and with CPodes. The counter
// "sim_per_wall" is simulated seconds per wall second: the target is at
// least 100 (calibration runs tens of thousands of trials). PegTrialStart is
// what a trial costs before it moves: the peg (experiments/scenes/
// peg_in_hole.json, V by ray casting) with its trial model built once, as an
// experiment builds it, and a time limit of 1 ms, so a trial is its set-up,
// its first decision (one V) and a millisecond of stepping. Run with
// tools/bench.
#include <benchmark/benchmark.h>

#include <string>

#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace {

void PegTrial(benchmark::State& state, const std::string& integrator) {
  vahf::scene::Scene scene = vahf::scene::LoadScene(
      std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/peg_in_hole_shell.json");
  scene.params.simulation.integrator = integrator;
  scene.params.simulation.accuracy = 1e-4;
  double simulated = 0;
  std::int64_t steps = 0, queries = 0;
  for (auto _ : state) {
    const vahf::sim::TrialResult r = vahf::sim::RunTrial(scene, {1, 0}, {0, 0.0, false});
    simulated += r.end_time;
    steps += r.counters.steps_taken;
    queries += r.counters.contact_point_queries;
    benchmark::DoNotOptimize(r.end_time);
  }
  state.counters["sim_per_wall"] =
      benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["steps"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kAvgIterations);
  state.counters["point_queries"] = benchmark::Counter(
      static_cast<double>(queries), benchmark::Counter::kAvgIterations);
}

BENCHMARK_CAPTURE(PegTrial, RungeKuttaMerson, std::string("RungeKuttaMerson"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(PegTrial, CPodes, std::string("CPodes"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(PegTrial, CVODE, std::string("CVODE"))->Unit(benchmark::kMillisecond);

void PegTrialStart(benchmark::State& state) {
  vahf::scene::Scene scene = vahf::scene::LoadScene(
      std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/peg_in_hole.json");
  scene.params.simulation.time_limit = 1e-3;
  const auto model = vahf::sim::BuildTrialModel(scene, 0);
  vahf::sim::TrialOptions options;
  options.record_trace = false;
  std::uint64_t k = 0;
  std::int64_t rays = 0;
  for (auto _ : state) {
    const vahf::sim::TrialResult r = vahf::sim::RunTrial(*model, {1, k++}, options);
    rays += r.counters.rays_cast;
    benchmark::DoNotOptimize(r.counters.decisions);
  }
  state.counters["rays"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kAvgIterations);
}
BENCHMARK(PegTrialStart)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
