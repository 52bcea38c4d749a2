// Cost of one contact evaluation, Jacobian included, on the states of a
// resolved trial: the peg in its bore and each cylinder part in its seat,
// for model "resolving" (the exact revolved contact for these revolved
// pairs) and "sampled" (the same law on the general path, sampled shell and
// rims). The states are the dense samples
// (every 0.1 ms) of one trial of the scene with contact/model resolving at
// its own integrator settings, seed 1, at most 50 000 steps, kept where the
// part is in contact; each is evaluated 20 times and timed alone. Counters: the
// median and 90th percentile over the states, in microseconds, and the
// states' count, and the queries and profile edges one evaluation makes on
// average. Run with tools/bench (one core).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace {

using vahf::contact::RigidMotion;

std::vector<RigidMotion> ContactStates(const vahf::sim::TrialModel& model) {
  vahf::sim::TrialOptions options;
  options.record_trace = false;
  options.sample_interval = 1e-4;
  const vahf::sim::TrialResult r = vahf::sim::RunTrial(model, {1, 0}, options);
  std::vector<RigidMotion> out;
  for (const vahf::sim::TraceRow& row : r.samples) {
    if (!(row.penetration > 0)) continue;
    RigidMotion m;
    m.pose.linear() = row.orientation.toRotationMatrix();
    m.pose.translation() = row.position;
    m.velocity = row.velocity;
    m.angular_velocity = row.angular_velocity;
    out.push_back(m);
  }
  return out;
}

void Evaluations(benchmark::State& state, const std::string& scene_file, int position,
                 const std::string& model_name) {
  vahf::scene::Scene scene = vahf::scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                                    "/experiments/scenes/" + scene_file);
  scene.params.contact.model = "resolving";
  scene.params.simulation.max_steps =
      50000;  // the cylinder parts' trials may stall at impacts
  const auto states = ContactStates(*vahf::sim::BuildTrialModel(scene, position));
  scene.params.contact.model = model_name;
  const auto model = vahf::sim::BuildTrialModel(scene, position);
  const vahf::contact::ContactModel& contact = *model->contact.model;
  if (states.empty()) {
    state.SkipWithError("no state in contact");
    return;
  }
  std::vector<double> micros(states.size()), forces_only(states.size());
  vahf::contact::ContactJacobian j;
  vahf::contact::ContactCounters work;
  for (const RigidMotion& m : states) contact.Evaluate(m, &work, &j);
  for (auto _ : state) {
    for (std::size_t k = 0; k < states.size(); ++k) {
      constexpr int kRepeats = 20;
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < kRepeats; ++i)
        benchmark::DoNotOptimize(contact.Evaluate(states[k], nullptr, &j));
      const auto middle = std::chrono::steady_clock::now();
      for (int i = 0; i < kRepeats; ++i)
        benchmark::DoNotOptimize(contact.Evaluate(states[k], nullptr, nullptr));
      const auto end = std::chrono::steady_clock::now();
      micros[k] =
          std::chrono::duration<double, std::micro>(middle - start).count() / kRepeats;
      forces_only[k] =
          std::chrono::duration<double, std::micro>(end - middle).count() / kRepeats;
    }
  }
  std::sort(micros.begin(), micros.end());
  std::sort(forces_only.begin(), forces_only.end());
  state.counters["states"] = static_cast<double>(states.size());
  state.counters["median_us"] = micros[micros.size() / 2];
  state.counters["p90_us"] = micros[micros.size() * 9 / 10];
  // Without the Jacobian: what a right-hand side pays.
  state.counters["forces_us"] = forces_only[forces_only.size() / 2];
  // The work behind the time, per evaluation: rim and shell point queries and
  // the profile edges they examined.
  const double n = static_cast<double>(states.size());
  state.counters["queries"] =
      static_cast<double>(work.rim_queries + work.point_queries) / n;
  state.counters["edges"] = static_cast<double>(work.edge_tests) / n;
}

#define VAHF_CONTACT_CASE(name, file, position)                                 \
  BENCHMARK_CAPTURE(Evaluations, name##_resolving, std::string(file), position, \
                    std::string("resolving"))                                   \
      ->Unit(benchmark::kMillisecond)                                           \
      ->Iterations(1);                                                          \
  BENCHMARK_CAPTURE(Evaluations, name##_sampled, std::string(file), position,   \
                    std::string("sampled"))                                     \
      ->Unit(benchmark::kMillisecond)                                           \
      ->Iterations(1)

VAHF_CONTACT_CASE(Peg, "peg_in_hole_resolved.json", 0);
VAHF_CONTACT_CASE(PistonRod, "hydraulic_cylinder.json", 0);
VAHF_CONTACT_CASE(GuideSleeve, "hydraulic_cylinder.json", 1);
VAHF_CONTACT_CASE(SealRing, "hydraulic_cylinder.json", 2);

}  // namespace

BENCHMARK_MAIN();
