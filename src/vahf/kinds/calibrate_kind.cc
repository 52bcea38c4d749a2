// The calibrate kind (docs/calibration.md): parameters fitted to a lab
// dataset's summaries by calibrate/calibration.h, written as a report and
// calibrated.json.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "vahf/calibrate/calibration.h"
#include "vahf/calibrate/targets.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/lab_run.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/calibration_section.h"

namespace vahf::kinds {
namespace {

// The lab dataset and the targets it must supply, as a run reads them before
// its first trial, and the scene's trial models.
std::string CheckCalibration(const scene::ExperimentFile& e) {
  const data::LabDataset lab =
      data::LoadLabDataset(e.Input<calibrate::CalibrationDesign>().lab_path);
  std::string out = data::DescribeLabDataset(lab);
  // Its operators, by the reach rule; its repetitions, by the cycles.
  calibrate::LabConditions(e.scene, lab, e.trials);
  for (const calibrate::CalibrationStage& stage :
       e.Input<calibrate::CalibrationDesign>().stages) {
    if (!stage.name.empty())
      out += fmt::format("  stage '{}' ({}):\n", stage.name, stage.solver);
    for (const calibrate::FitParameter& p : stage.parameters)
      out += fmt::format("  fits {} from {:g} within [{:g}, {:g}]\n", p.name, p.start,
                         p.lower, p.upper);
    for (const auto& t : calibrate::LabTargets(e.scene, lab, stage.targets, e.file)) {
      if (t.lab.single_draw)
        out += fmt::format(
            "  target {}: lab {:g} (one draw: weighed by the virtual spread)\n", t.label,
            t.lab.value);
      else
        out += fmt::format("  target {}: lab {:g} (se {:g}, n {})\n", t.label,
                           t.lab.value, std::sqrt(t.lab.variance), t.lab.n);
    }
  }
  return out + DescribeSceneModels(e.scene);
}

// Ceres' fit with a line of progress per design evaluation (stderr), then the
// output directory with calibrated.json.
int RunCalibration(const scene::ExperimentFile& file, const RunContext& context) {
  const experiment::RunSettings& settings = context.settings;
  const data::LabDataset lab =
      data::LoadLabDataset(file.Input<calibrate::CalibrationDesign>().lab_path);
  const int trials = settings.trials > 0 ? settings.trials : file.trials;
  const experiment::RunnerOptions options =
      experiment::RunnerOptionsOf(settings, file.name + " (calibrate)");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<calibrate::CalibrationResult> stages = calibrate::Calibrate(
      file.scene, lab, file.Input<calibrate::CalibrationDesign>(), file.file,
      settings.seed, trials, options, [&](const std::string& line) {
        if (settings.progress) std::fprintf(stderr, "%s\n", line.c_str());
      });
  const report::RunInfo info = RunInfoOf(settings, start);
  const report::RunOutput written = WriteLabRun(
      file, lab, context, trials, " per lab operator and parameter vector",
      KindSection(context, report::CalibrationSection(file, lab, stages)), info);
  int evaluations = 0;
  for (const auto& r : stages) {
    evaluations += r.evaluations;
    for (const auto& p : r.parameters)
      if (p.identified)
        std::printf("%s = %.6g, standard error %.3g, 95 %% interval [%.6g, %.6g]\n",
                    p.name.c_str(), p.estimate, p.standard_error, p.ci.lower, p.ci.upper);
      else
        std::printf("%s = %.6g, not identified: %s\n", p.name.c_str(), p.estimate,
                    p.not_identified_why.c_str());
  }
  const int status = FinishRun(file, context, info.wall_seconds, written,
                               fmt::format("{} evaluations", evaluations));
  std::printf("overrides: %s/%s\n", context.directory->path().c_str(),
              report::kOverridesFile);
  return status;
}

}  // namespace

Kind CalibrateKind() {
  Kind k;
  k.name = "calibrate";
  k.summary = "parameters fitted to a lab dataset (docs/calibration.md)";
  k.doc = "calibration.md#the-calibrate-kind";
  k.keys = {"lab",        "fatigue",       "parameters",       "targets",
            "loss",       "relative_step", "max_iterations",   "tolerance",
            "solver",     "stages",        "noise_replicates", "intervals",
            "line_search"};
  k.parse = calibrate::ReadCalibration;
  k.check = CheckCalibration;
  k.run = RunCalibration;
  return k;
}

}  // namespace vahf::kinds
