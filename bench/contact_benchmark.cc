// Cost of one contact evaluation, Jacobian included, on the states of a
// resolved trial: the peg in its bore and each cylinder part in its seat,
// for model "resolving" (the exact revolved contact for these revolved
// pairs) and "sampled" (the same law on the general path, sampled shell and
// rims). The states are the dense samples
// (every 0.1 ms) of one trial of the scene with contact/model resolving at
// its own integrator settings, seed 1, at most 50 000 steps, kept where the
// part is in contact; each is evaluated 20 times and timed alone, in 5 rounds.
// Counters: the median over the states (with the Jacobian, median_us; without,
// forces_us) and their 90th percentile, in microseconds, each the median of
// the 5 rounds' (median_least_us and median_greatest_us the rounds' spread);
// the states' count; and the queries and profile edges one evaluation makes
// on average. The peg and the piston rod also oiled (the same states, the
// squeeze film added). Run with tools/bench (one core).
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
                 const std::string& model_name, double viscosity = 0.0) {
  vahf::scene::Scene scene = vahf::scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                                    "/experiments/scenes/" + scene_file);
  scene.params.contact.model = "resolving";
  scene.params.simulation.max_steps =
      50000;  // the cylinder parts' trials may stall at impacts
  const auto states = ContactStates(*vahf::sim::BuildTrialModel(scene, position));
  scene.params.contact.model = model_name;
  scene.params.contact.lubricant_viscosity = viscosity;
  const auto model = vahf::sim::BuildTrialModel(scene, position);
  const vahf::contact::ContactModel& contact = *model->contact.model;
  if (states.empty()) {
    state.SkipWithError("no state in contact");
    return;
  }
  vahf::contact::ContactJacobian j;
  vahf::contact::ContactCounters work;
  for (const RigidMotion& m : states) contact.Evaluate(m, &work, &j);
  // kRounds rounds over the states; in each, every state is evaluated
  // kRepeats times with the Jacobian and kRepeats without, and timed alone.
  // A round's figure is the median over the states; the counters are the
  // median of the rounds' figures and their spread (least, greatest), so
  // that an interruption of the machine moves a round, not the figure.
  constexpr int kRounds = 5, kRepeats = 20;
  std::vector<double> with_jacobian, forces_only, p90;
  for (auto _ : state) {
    for (int round = 0; round < kRounds; ++round) {
      std::vector<double> micros(states.size()), forces(states.size());
      for (std::size_t k = 0; k < states.size(); ++k) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < kRepeats; ++i)
          benchmark::DoNotOptimize(contact.Evaluate(states[k], nullptr, &j));
        const auto middle = std::chrono::steady_clock::now();
        for (int i = 0; i < kRepeats; ++i)
          benchmark::DoNotOptimize(contact.Evaluate(states[k], nullptr, nullptr));
        const auto end = std::chrono::steady_clock::now();
        micros[k] =
            std::chrono::duration<double, std::micro>(middle - start).count() / kRepeats;
        forces[k] =
            std::chrono::duration<double, std::micro>(end - middle).count() / kRepeats;
      }
      std::sort(micros.begin(), micros.end());
      std::sort(forces.begin(), forces.end());
      with_jacobian.push_back(micros[micros.size() / 2]);
      p90.push_back(micros[micros.size() * 9 / 10]);
      forces_only.push_back(forces[forces.size() / 2]);
    }
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  state.counters["states"] = static_cast<double>(states.size());
  state.counters["median_us"] = median(with_jacobian);
  state.counters["median_least_us"] =
      *std::min_element(with_jacobian.begin(), with_jacobian.end());
  state.counters["median_greatest_us"] =
      *std::max_element(with_jacobian.begin(), with_jacobian.end());
  state.counters["p90_us"] = median(p90);
  // Without the Jacobian: what a right-hand side pays.
  state.counters["forces_us"] = median(forces_only);
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

VAHF_CONTACT_CASE(Peg, "peg_in_hole.json", 0);
VAHF_CONTACT_CASE(PistonRod, "hydraulic_cylinder.json", 0);
VAHF_CONTACT_CASE(GuideSleeve, "hydraulic_cylinder.json", 1);
VAHF_CONTACT_CASE(SealRing, "hydraulic_cylinder.json", 2);

// The same states with the fit oiled (VG 46 at about 25 C, 0.085 Pa s): the
// squeeze film (squeeze_film.h) added to the exact contact, its Jacobian by
// forward-mode AutoDiff.
BENCHMARK_CAPTURE(Evaluations, Peg_resolving_oiled, std::string("peg_in_hole.json"), 0,
                  std::string("resolving"), 0.085)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(Evaluations, PistonRod_resolving_oiled,
                  std::string("hydraulic_cylinder.json"), 0, std::string("resolving"),
                  0.085)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
