// The compare kind (docs/calibration.md, "Compare"): a virtual design against
// a lab dataset, quantity by quantity (compare/comparison.h).
#include <fmt/format.h>

#include <chrono>
#include <cstdio>

#include "vahf/calibrate/targets.h"
#include "vahf/compare/comparison.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/lab_run.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/compare_section.h"

namespace vahf::kinds {
namespace {

// The lab's side of every quantity, as a run reads it before simulating, and
// the scene's trial models.
std::string CheckComparison(const scene::ExperimentFile& e) {
  const data::LabDataset lab =
      data::LoadLabDataset(e.Input<compare::ComparisonDesign>().lab_path);
  std::string out = data::DescribeLabDataset(lab);
  // Its operators, by the reach rule; its repetitions, by the cycles.
  calibrate::LabConditions(e.scene, lab, e.trials);
  bool segments = false;
  for (const auto& q :
       compare::LabSide(e.scene, lab, e.Input<compare::ComparisonDesign>(), e.file)) {
    const char* unit = q.target.unit == "s" ? " s" : "";
    out += fmt::format("  compares {} within +-{:g}{}: lab {:g}{} from {}\n",
                       q.target.label, q.margin, unit, q.target.lab.value, unit,
                       compare::LabBasis(q.target, q.reported));
    segments = segments || q.target.spec.segment > 0;
  }
  const scene::FatigueDesign& f = e.Input<compare::ComparisonDesign>().fatigue;
  if (segments)
    out += fmt::format(
        "  segments from the fatigue design: {:g} min in {} segments, {} pilot "
        "cycles\n",
        f.duration_min, f.segments, f.pilot_cycles > 0 ? f.pilot_cycles : e.trials);
  return out + DescribeSceneModels(e.scene);
}

// The lab's operators and the fatigue design's pilot and segments, as the
// comparison runs them (compare/comparison.h), for `vahf replay`.
std::vector<experiment::Condition> CompareConditions(
    const scene::ExperimentFile& file, const experiment::RunSettings& settings) {
  const compare::ComparisonDesign& design = file.Input<compare::ComparisonDesign>();
  const int trials = settings.trials > 0 ? settings.trials : file.trials;
  std::vector<experiment::Condition> out =
      calibrate::LabConditions(file.scene, data::LoadLabDataset(design.lab_path), trials);
  for (experiment::Condition& c : experiment::FatigueDesignConditions(
           std::make_shared<const scene::Scene>(file.scene), design.fatigue))
    out.push_back(std::move(c));
  return out;
}

int RunComparison(const scene::ExperimentFile& file, const RunContext& context) {
  const experiment::RunSettings& settings = context.settings;
  const data::LabDataset lab =
      data::LoadLabDataset(file.Input<compare::ComparisonDesign>().lab_path);
  const int trials = settings.trials > 0 ? settings.trials : file.trials;
  const experiment::RunnerOptions options =
      experiment::RunnerOptionsOf(settings, file.name + " (compare)");
  experiment::RunnerOptions pilot_options = options;
  pilot_options.label = file.name + " (compare, fatigue pilot)";
  const auto start = std::chrono::steady_clock::now();
  const compare::ComparisonResult result =
      compare::Compare(file.scene, lab, file.Input<compare::ComparisonDesign>(),
                       file.file, settings.seed, trials, options, pilot_options);
  const report::RunInfo info = RunInfoOf(settings, start);
  const report::RunOutput written = WriteLabRun(
      file, lab, context, trials,
      result.fatigue.run.conditions.empty() ? " per lab operator"
      : result.run.conditions.empty()       ? " per segment"
                                            : " per lab operator and per segment",
      KindSection(context, report::ComparisonSection(file, lab, result, trials)), info);
  for (const auto& q : result.quantities)
    std::printf("%s: %s\n", q.target.label.c_str(), q.verdict.c_str());
  return FinishRun(file, context, info.wall_seconds, written);
}

}  // namespace

Kind CompareKind() {
  Kind k;
  k.name = "compare";
  k.summary = "a virtual design against a lab dataset (docs/calibration.md)";
  k.doc = "experiments.md#compare-virtual-against-a-lab-dataset";
  k.keys = {"lab", "fatigue", "quantities"};
  k.parse = compare::ReadComparison;
  k.check = CheckComparison;
  k.run = RunComparison;
  k.conditions = CompareConditions;
  return k;
}

}  // namespace vahf::kinds
