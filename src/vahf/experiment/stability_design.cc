#include "vahf/experiment/stability_design.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "vahf/experiment/cycle.h"
#include "vahf/experiment/result_codec.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace vahf::experiment {
namespace {

bool Finite(const sim::TraceRow& r) {
  const human::FactorValues& f = r.factors;
  return std::isfinite(r.time) && r.position.allFinite() &&
         r.orientation.coeffs().allFinite() && r.velocity.allFinite() &&
         r.angular_velocity.allFinite() && r.assembly_force.allFinite() &&
         r.contact_force.allFinite() && r.friction_force.allFinite() &&
         std::isfinite(r.work) && std::isfinite(r.psi) && std::isfinite(r.penetration) &&
         std::isfinite(f.V) && std::isfinite(f.f) && std::isfinite(f.eta) &&
         std::isfinite(f.r) && std::isfinite(f.g) && std::isfinite(f.lambda_c) &&
         std::isfinite(f.shoulder_distance);
}

}  // namespace

std::vector<std::string> OutcomeClasses() {
  std::vector<std::string> out;
  for (sim::Status s :
       {sim::Status::kCompleted, sim::Status::kTimeout, sim::Status::kExhausted,
        sim::Status::kUnreachable, sim::Status::kJammed, sim::Status::kNumericalFailure,
        sim::Status::kStepBudget})
    out.push_back(sim::StatusName(s));
  return out;
}

bool IsOutcomeClass(const std::string& name) {
  const std::vector<std::string> all = OutcomeClasses();
  return std::find(all.begin(), all.end(), name) != all.end();
}

std::vector<std::string> StabilityFailures(const StabilityCase& c,
                                           const sim::TrialResult& r,
                                           std::int64_t max_steps) {
  std::vector<std::string> out;
  const std::string status = sim::StatusName(r.status);
  if (std::find(c.expect.begin(), c.expect.end(), status) == c.expect.end())
    out.push_back(
        fmt::format("ended {}, expected {}", status, fmt::join(c.expect, " or ")));
  std::vector<std::string> bad;
  if (!std::isfinite(r.end_time)) bad.push_back("end time");
  if (!std::isfinite(r.work)) bad.push_back("work");
  if (!std::isfinite(r.max_penetration)) bad.push_back("deepest contact");
  if (!Finite(r.final_row)) bad.push_back("final row");
  if (!bad.empty()) out.push_back(fmt::format("not finite: {}", fmt::join(bad, ", ")));
  if (r.counters.steps_taken > max_steps)
    out.push_back(fmt::format("{} accepted steps, over simulation/max_steps {}",
                              r.counters.steps_taken, max_steps));
  return out;
}

std::vector<StabilityTrial> RunStabilityTrials(const StabilityDesign& design,
                                               std::uint64_t seed,
                                               const RunnerOptions& options) {
  // The models of every case and integrator, built (and checked) once before
  // any trial runs; the index of every trial.
  std::vector<std::vector<std::shared_ptr<const sim::TrialModel>>> models;
  std::vector<StabilityTrial> plan;
  for (std::size_t k = 0; k < design.cases.size(); ++k) {
    const StabilityCase& c = design.cases[k];
    models.emplace_back();
    for (std::size_t i = 0; i < c.scenes.size(); ++i) {
      models.back().push_back(sim::BuildTrialModel(c.scenes[i], c.position));
      for (int j = 0; j < c.seeds; ++j) {
        StabilityTrial t;
        t.case_index = k;
        t.integrator_index = i;
        t.seed_index = j;
        plan.push_back(std::move(t));
      }
    }
  }
  const std::function<StabilityTrial(std::size_t)> trial = [&](std::size_t n) {
    StabilityTrial t = plan[n];
    const StabilityCase& c = design.cases[t.case_index];
    const scene::Scene& scene = c.scenes[t.integrator_index];
    sim::TrialOptions trial_options;
    trial_options.sequence_position = c.position;
    trial_options.record_trace = false;
    t.result = sim::RunTrial(
        *models[t.case_index][t.integrator_index],
        CycleKey(seed, static_cast<std::uint64_t>(t.seed_index), scene.sequence.size(),
                 static_cast<std::size_t>(c.position)),
        trial_options);
    t.failures = StabilityFailures(c, t.result, scene.params.simulation.max_steps);
    return t;
  };
  return RunIndexed<StabilityTrial>(plan.size(), options, trial, &kStabilityTrialCodec);
}

}  // namespace vahf::experiment
