// CPU per trial over many seeds (docs/performance.md): the peg and each of the
// hydraulic cylinder's three parts, per integrator at accuracy 1e-4 and at the
// cylinder scene's own setting (and the peg and the piston rod with the
// contact that resolves their fits), trials
// keyed {1, k} for k < VAHF_BENCH_SEEDS (default 200), one core, the part's
// trial model built once. Counters: thread CPU seconds per trial at p50, p99
// and max; the real-time factor (simulated over CPU seconds) at p50 and its
// worst; mean contact evaluations, integrator steps and rejected steps
// (attempted - taken) per trial; completed share; CPU per accepted step; the
// shares of the time in contact, Jacobians, linear algebra, the operator's
// hand, decisions, visibility and the rest (TrialOptions::time_phases,
// phase_seconds.h). One benchmark iteration
// runs every seed. Run with tools/bench --benchmark_filter=Seeds.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "vahf/core/thread_cpu.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace {

int SeedCount() {
  const char* env = std::getenv("VAHF_BENCH_SEEDS");
  const int n = env ? std::atoi(env) : 200;
  return n > 0 ? n : 200;
}

// The q quantile of sorted values, nearest rank.
double Quantile(const std::vector<double>& sorted, double q) {
  const std::size_t k =
      static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1) + 0.5);
  return sorted[std::min(k, sorted.size() - 1)];
}

// `integrator` at accuracy 1e-4 (and CVODE's default velocity time scale),
// or, when empty, the scene's own setting; with `contact_model`, that model,
// at most 100 000 steps a trial (a trial that stalls at an impact ends
// step_budget in about 2 s instead of 20 s), CVODE's BDF order at most 2, a
// Jacobian at least every 5 steps and the operator's friction push bounded
// at 100 N (what a contact held by the hardening barrier needs:
// docs/physics.md).
namespace settings = vahf::scene::stepper_settings;

void Seeds(benchmark::State& state, const std::string& scene_file, int position,
           const std::string& integrator, const std::string& contact_model = "") {
  vahf::scene::Scene scene = vahf::scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                                    "/experiments/scenes/" + scene_file);
  if (!contact_model.empty()) {
    scene.params.contact.model = contact_model;
    scene.params.simulation.max_steps = 100000;
    scene.params.simulation.stepper_values.Upd(settings::max_order) = 2;
    scene.params.simulation.stepper_values.Upd(settings::jacobian_interval) = 5;
    scene.params.guidance.max_push = 100;
  }
  if (!integrator.empty()) {
    scene.params.simulation.integrator = integrator;
    scene.params.simulation.accuracy = 1e-4;
    scene.params.simulation.stepper_values.Upd(settings::velocity_time_scale) =
        settings::velocity_time_scale.default_value;
  }
  const auto model = vahf::sim::BuildTrialModel(scene, position);
  const int n = SeedCount();
  std::vector<double> cpu, rtf;
  double evaluations = 0, steps = 0, rejected = 0, completed = 0;
  vahf::sim::PhaseSeconds phases;
  double wall = 0;
  vahf::sim::TrialOptions options;
  options.record_trace = false;
  options.time_phases = true;
  for (auto _ : state) {
    cpu.clear();
    rtf.clear();
    for (int k = 0; k < n; ++k) {
      const double start = vahf::ThreadCpuSeconds();
      const vahf::sim::TrialResult r =
          vahf::sim::RunTrial(*model, {1, static_cast<std::uint64_t>(k)}, options);
      const double seconds = vahf::ThreadCpuSeconds() - start;
      cpu.push_back(seconds);
      rtf.push_back(r.end_time / seconds);
      evaluations += static_cast<double>(r.counters.contact_evaluations);
      steps += static_cast<double>(r.counters.steps_taken);
      rejected +=
          static_cast<double>(r.counters.steps_attempted - r.counters.steps_taken);
      completed += r.status == vahf::sim::Status::kCompleted ? 1 : 0;
      phases.contact += r.phases.contact;
      phases.jacobian += r.phases.jacobian;
      phases.linear_algebra += r.phases.linear_algebra;
      phases.hand += r.phases.hand;
      phases.decisions += r.phases.decisions;
      phases.visibility += r.phases.visibility;
      wall += r.wall_seconds;
    }
  }
  std::sort(cpu.begin(), cpu.end());
  std::sort(rtf.begin(), rtf.end());
  const double trials = static_cast<double>(n) * static_cast<double>(state.iterations());
  state.counters["cpu_p50_s"] = Quantile(cpu, 0.5);
  state.counters["cpu_p99_s"] = Quantile(cpu, 0.99);
  state.counters["cpu_max_s"] = cpu.back();
  state.counters["rtf_p50"] = Quantile(rtf, 0.5);
  state.counters["rtf_min"] = rtf.front();
  state.counters["evals"] = evaluations / trials;
  state.counters["steps"] = steps / trials;
  state.counters["rejected"] = rejected / trials;
  state.counters["completed"] = completed / trials;
  // CPU per accepted step, everything included.
  double cpu_total = 0;
  for (double c : cpu) cpu_total += c;
  state.counters["us_per_step"] =
      1e6 * cpu_total / static_cast<double>(n) / (steps / trials);
  // Where the time went, as shares of the trials' wall time (one core):
  // contact evaluations (the oil's film among them), analytic Jacobians
  // (CVODE), the linear solver (CVODE), the operator's hand at each
  // right-hand side, the decisions, V's ray casting, and the rest (the
  // stepper itself and the step checks; for Simbody's steppers also their
  // Jacobians and linear algebra).
  state.counters["share_contact"] = phases.contact / wall;
  state.counters["share_jacobian"] = phases.jacobian / wall;
  state.counters["share_linalg"] = phases.linear_algebra / wall;
  state.counters["share_hand"] = phases.hand / wall;
  state.counters["share_decisions"] = phases.decisions / wall;
  state.counters["share_visibility"] = phases.visibility / wall;
  state.counters["share_rest"] =
      1.0 - (phases.contact + phases.jacobian + phases.linear_algebra + phases.hand +
             phases.decisions + phases.visibility) /
                wall;
}

// One benchmark: `name` over the seeds of `file`'s part `position` with
// `integrator` (the empty string: the scene's own setting).
#define VAHF_SEEDS_ONE(name, file, position, integrator)                               \
  BENCHMARK_CAPTURE(Seeds, name, std::string(file), position, std::string(integrator)) \
      ->Iterations(1)                                                                  \
      ->Unit(benchmark::kSecond);
// The shipped scenes (resolved fits, the wrist, the oiled cylinder) at their
// own settings: what experiments/precision_peg_resolved.json and
// precision_cylinder_resolved.json accept, and the paper run uses.
VAHF_SEEDS_ONE(peg_scene_setting, "peg_in_hole.json", 0, "")
VAHF_SEEDS_ONE(piston_rod_scene_setting, "hydraulic_cylinder.json", 0, "")
VAHF_SEEDS_ONE(guide_sleeve_scene_setting, "hydraulic_cylinder.json", 1, "")
VAHF_SEEDS_ONE(seal_ring_scene_setting, "hydraulic_cylinder.json", 2, "")
// The peg under CPodes, its precision reference; and the same contact law on
// the sampled general path (contact/model sampled) under CVODE.
VAHF_SEEDS_ONE(peg_CPodes, "peg_in_hole.json", 0, "CPodes")
BENCHMARK_CAPTURE(Seeds, peg_sampled_CVODE, std::string("peg_in_hole.json"), 0,
                  std::string("CVODE"), std::string("sampled"))
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
// The shell scenes (the point-shell contact that does not resolve the fits,
// the inertial torque law, dry): each part with RungeKuttaMerson and CVODE at
// 1e-4, and at its scene's own setting (what experiments/precision_peg.json
// and precision_cylinder.json recommend for them).
#define VAHF_SEEDS(name, file, position)                                      \
  VAHF_SEEDS_ONE(name##_RungeKuttaMerson, file, position, "RungeKuttaMerson") \
  VAHF_SEEDS_ONE(name##_CVODE, file, position, "CVODE")                       \
  VAHF_SEEDS_ONE(name##_scene_setting, file, position, "")

VAHF_SEEDS(peg_shell, "peg_in_hole_shell.json", 0)
VAHF_SEEDS(piston_rod_shell, "hydraulic_cylinder_shell.json", 0)
VAHF_SEEDS(guide_sleeve_shell, "hydraulic_cylinder_shell.json", 1)
VAHF_SEEDS(seal_ring_shell, "hydraulic_cylinder_shell.json", 2)

}  // namespace

BENCHMARK_MAIN();
