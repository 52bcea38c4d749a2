// The stability kind (docs/experiments.md, "stability"): stiff and extreme
// cases across integrators, each with the outcome classes its file expects;
// the run fails (exit 1, its outputs written) when a case ends otherwise,
// with a number that is not finite, or beyond its step budget.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "vahf/core/error.h"
#include "vahf/experiment/stability_design.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/stability_section.h"
#include "vahf/sim/trial_model.h"

namespace vahf::kinds {
namespace {

// The expected classes (trial status names, which the scene layer does not
// know), and every case's trial model under every integrator.
std::string CheckStability(const scene::ExperimentFile& file) {
  for (const experiment::StabilityCase& c :
       file.Input<experiment::StabilityDesign>().cases)
    for (std::size_t j = 0; j < c.expect.size(); ++j)
      if (!experiment::IsOutcomeClass(c.expect[j]))
        throw InputError(file.file, c.expect_pointers[j], c.expect[j],
                         fmt::format("an outcome class is a trial status: {}",
                                     fmt::join(experiment::OutcomeClasses(), ", ")));
  std::string out = experiment::DescribeStability(file);
  for (const experiment::StabilityCase& c :
       file.Input<experiment::StabilityDesign>().cases)
    for (const scene::Scene& scene : c.scenes) sim::BuildTrialModel(scene, c.position);
  return out;
}

int RunStability(const scene::ExperimentFile& file, const RunContext& context) {
  const experiment::RunSettings& settings = context.settings;
  const experiment::RunnerOptions options =
      experiment::RunnerOptionsOf(settings, file.name + " (stability)", "trials");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<experiment::StabilityTrial> trials = experiment::RunStabilityTrials(
      file.Input<experiment::StabilityDesign>(), settings.seed, options);
  const report::RunInfo info = RunInfoOf(settings, start);
  report::RunHeader h;
  h.file = &file;
  h.first = &file;
  h.seed = settings.seed;
  h.trials = 1;
  h.cycles_per_condition = "each case's seeds per integrator";
  for (const experiment::StabilityCase& c :
       file.Input<experiment::StabilityDesign>().cases)
    if (std::find(h.inputs.begin(), h.inputs.end(), c.scene_path) == h.inputs.end())
      h.inputs.push_back(c.scene_path);
  h.integration = fmt::format(
      "per case and integrator, accuracy {:g} unless the case sets "
      "it (stability_trials.csv)",
      file.scene.params.simulation.accuracy);
  if (!file.overrides_path.empty()) h.inputs.push_back(file.overrides_path);
  const report::RunOutput written = report::WriteSections(
      h, {KindSection(context, report::StabilitySection(file, trials))},
      *context.directory, info);
  const std::vector<std::string> failed =
      report::FailedCases(file.Input<experiment::StabilityDesign>(), trials);
  const int status = FinishRun(
      file, context, info.wall_seconds, written,
      fmt::format("{} trials, {} of {} cases passed", trials.size(),
                  file.Input<experiment::StabilityDesign>().cases.size() - failed.size(),
                  file.Input<experiment::StabilityDesign>().cases.size()));
  if (failed.empty()) return status;
  std::fprintf(stderr, "vahf: error: stability: %zu case(s) failed (results kept): %s\n",
               failed.size(), fmt::format("{}", fmt::join(failed, ", ")).c_str());
  return kExitComputationFailure;  // a failed case: the suite's computation failed
}

}  // namespace

Kind StabilityKind() {
  Kind k;
  k.name = "stability";
  k.summary =
      "stiff and extreme cases across integrators, each with its expected outcome";
  k.doc = "experiments.md#stability-stiff-and-extreme-cases-across-integrators";
  k.keys = {"integrators", "cases"};
  k.scene_elsewhere = "a stability experiment names a scene in each of its \"cases\"";
  k.parse = experiment::ReadStability;
  k.check = CheckStability;
  k.run = RunStability;
  k.cycles_per_condition = false;  // each case's seeds per integrator
  return k;
}

}  // namespace vahf::kinds
