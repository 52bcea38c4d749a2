// The vahf command: validates scene, experiment and lab dataset files, checks
// the paper's reference values, and (as the harness grows) runs trials and
// experiments.
// Exit status: 0 success; 1 a failure of the computation, stated on stderr
// (for `vahf trial`: the trial ended other than completed, its summary still
// printed); 2 bad input (a file, a value or an option), in one line; 130
// interrupted.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>

#include "vahf/calibrate/calibration.h"
#include "vahf/calibrate/synthetic_lab.h"
#include "vahf/compare/comparison.h"
#include "vahf/core/atomic_file.h"
#include "vahf/core/error.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/design.h"
#include "vahf/experiment/interrupt.h"
#include "vahf/experiment/table1_reference.h"
#include "vahf/report/calibration_section.h"
#include "vahf/report/compare_section.h"
#include "vahf/report/run_output.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/overrides.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trace_csv.h"
#include "vahf/sim/trial.h"

namespace {

// Builds the scene's trial models, as a run would before its first trial
// (what only building can reject is rejected now), and says what each holds.
void CheckModels(const vahf::scene::Scene& scene) {
  for (const auto& m : vahf::sim::BuildSequenceModels(scene)) {
    std::printf("  trial model '%s': ", m->part->name.c_str());
    if (!m->contact.model)
      std::printf("nothing to touch");
    else
      std::printf("contact %s, %lld shell points", scene.params.contact.model.c_str(),
                  static_cast<long long>(m->contact.shell_points));
    if (m->clearance > 0)
      std::printf(", radial clearance %.3g um, penetration bound %.3g um",
                  m->clearance * 1e6, m->penetration_bound * 1e6);
    std::printf("%s\n", m->visibility ? ", V by ray casting" : "");
  }
}

// A calibration's lab dataset and the targets it must supply, as a run
// would read them before its first trial.
void CheckCalibration(const vahf::scene::ExperimentFile& e) {
  const vahf::data::LabDataset lab = vahf::data::LoadLabDataset(e.calibration.lab_path);
  std::fputs(vahf::data::DescribeLabDataset(lab).c_str(), stdout);
  vahf::calibrate::LabConditions(e.scene, lab, 1);  // its operators, by the reach rule
  for (const vahf::scene::CalibrationStage& stage : e.calibration.stages) {
    if (!stage.name.empty())
      std::printf("  stage '%s' (%s):\n", stage.name.c_str(), stage.solver.c_str());
    for (const vahf::scene::FitParameter& p : stage.parameters)
      std::printf("  fits %s from %g within [%g, %g]\n", p.name.c_str(), p.start, p.lower,
                  p.upper);
    for (const auto& t : vahf::calibrate::LabTargets(lab, stage.targets, e.file)) {
      if (t.lab.single_draw)
        std::printf("  target %s: lab %g (one draw: weighed by the virtual spread)\n",
                    t.label.c_str(), t.lab.value);
      else
        std::printf("  target %s: lab %g (se %g, n %d)\n", t.label.c_str(), t.lab.value,
                    std::sqrt(t.lab.variance), t.lab.n);
    }
  }
  std::fputs(vahf::scene::DescribeScene(e.scene).c_str(), stdout);
  CheckModels(e.scene);
}

int Check(const std::string& path) {
  const nlohmann::json document = vahf::scene::ReadJsonFile(path);  // read once
  const std::string format = vahf::scene::FormatOf(document, path);
  if (format == "lab") {
    std::fputs(vahf::data::DescribeLabDataset(vahf::data::ParseLabDataset(document, path))
                   .c_str(),
               stdout);
  } else if (format == "overrides") {
    const vahf::scene::ParameterOverrides o = vahf::scene::LoadOverrides(path);
    std::printf("parameter overrides (%s)%s%s\n", path.c_str(), o.source.empty() ? "" : ": ",
                o.source.c_str());
    for (const auto& [name, value] : o.values)
      std::printf("  %s = %s\n", name.c_str(), value.dump().c_str());
  } else if (format == "synthetic") {
    const vahf::calibrate::SyntheticLabSpec spec = vahf::calibrate::LoadSyntheticLabSpec(path);
    std::printf("synthetic lab '%s': scene %s, %zu operator(s) x %d repetitions, seed %llu, "
                "reading error sd %g s, resolution %g s\n",
                spec.name.c_str(), spec.scene_path.c_str(), spec.operators.size(),
                spec.repetitions, static_cast<unsigned long long>(spec.seed), spec.time_sd,
                spec.time_resolution);
    for (const auto& [name, value] : spec.truth)
      std::printf("  %s = %g (stated)\n", name.c_str(), value);
    CheckModels(spec.scene);
  } else if (format == "scene") {
    const vahf::scene::Scene scene = vahf::scene::ParseScene(document, path);
    std::fputs(vahf::scene::DescribeScene(scene).c_str(), stdout);
    CheckModels(scene);
  } else {
    const vahf::scene::ExperimentFile e = vahf::scene::ParseExperiment(document, path);
    std::printf("experiment '%s' (%s): kind %s, seed %llu%s\n", e.name.c_str(),
                e.file.c_str(), e.kind.c_str(), static_cast<unsigned long long>(e.seed),
                e.kind == "paper"
                    ? ""
                    : (", " + std::to_string(e.trials) + " cycles per condition").c_str());
    if (e.kind == "precision") {
      std::fputs(vahf::scene::DescribePrecision(e).c_str(), stdout);
    } else if (e.kind == "calibrate") {
      CheckCalibration(e);
    } else if (e.kind == "compare") {
      const vahf::data::LabDataset lab = vahf::data::LoadLabDataset(e.comparison.lab_path);
      std::fputs(vahf::data::DescribeLabDataset(lab).c_str(), stdout);
      vahf::calibrate::LabConditions(e.scene, lab, 1);  // its operators, by the reach rule
      // The lab's side of every quantity, as a run reads it before simulating.
      bool segments = false;
      for (const auto& q : vahf::compare::LabSide(lab, e.comparison, e.file)) {
        const char* unit = q.target.unit == "s" ? " s" : "";
        std::printf("  compares %s within +-%g%s: lab %g%s from %s\n", q.target.label.c_str(),
                    q.margin, unit, q.target.lab.value, unit,
                    vahf::compare::LabBasis(q.target, q.reported).c_str());
        segments = segments || q.target.spec.segment > 0;
      }
      const vahf::scene::FatigueDesign& f = e.comparison.fatigue;
      if (segments)
        std::printf("  segments from the fatigue design: %g min in %d segments, %d pilot "
                    "cycles\n",
                    f.duration_min, f.segments, f.pilot_cycles > 0 ? f.pilot_cycles : e.trials);
      std::fputs(vahf::scene::DescribeScene(e.scene).c_str(), stdout);
      CheckModels(e.scene);
    } else if (e.kind == "paper") {
      for (const vahf::scene::ExperimentFile& x : e.experiments)
        std::printf("  %s (%s): kind %s, %d cycles per condition, scene %s\n",
                    x.name.c_str(), x.file.c_str(), x.kind.c_str(), x.trials,
                    x.scene_path.c_str());
    } else {
      std::fputs(vahf::scene::DescribeScene(e.scene).c_str(), stdout);
      CheckModels(e.scene);
    }
  }
  std::printf("%s: valid %s\n", path.c_str(),
              format == "lab"         ? "lab dataset"
              : format == "overrides" ? "parameter override file"
              : format == "synthetic" ? "synthetic lab generator"
                                      : format.c_str());
  return 0;
}

int Reference(const std::string& table_path) {
  const vahf::experiment::Table1 table = vahf::experiment::LoadTable1(table_path);
  const auto checks = vahf::experiment::CheckTable1(table);
  std::fputs(vahf::experiment::FormatTable1Check(table, checks).c_str(), stdout);
  return 0;
}

struct TrialArgs {
  std::string scene;
  std::uint64_t seed = 1;
  std::uint64_t trial = 0;
  int position = 0;
  std::string integrator;
  double accuracy = 0;
  std::string trace;
  double sample = 0;
};

// The scene's file kind, told apart before it is read as a scene: another
// vahf file is named as such, with the command that takes it.
void ExpectSceneFile(const nlohmann::json& document, const std::string& path) {
  const std::string format = vahf::scene::FormatOf(document, path);
  if (format == "scene") return;
  const char* what = format == "experiment"  ? "an experiment file (run it with `vahf run`)"
                     : format == "lab"       ? "a lab dataset (compare or calibrate against it "
                                               "with an experiment file and `vahf run`)"
                     : format == "overrides" ? "a parameter override file (apply it with "
                                               "`vahf run EXPERIMENT --overrides FILE`)"
                                             : "a synthetic lab generator (run it with "
                                               "`vahf synthesize`)";
  vahf::scene::JsonNode(document, path)
      .Required("format")
      .Fail(fmt::format("this is {}; `vahf trial` takes a scene file", what));
}

int Trial(const TrialArgs& a) {
  const nlohmann::json document = vahf::scene::ReadJsonFile(a.scene);
  ExpectSceneFile(document, a.scene);
  vahf::scene::Scene scene = vahf::scene::ParseScene(document, a.scene);
  if (!a.integrator.empty()) scene.params.simulation.integrator = a.integrator;
  if (a.accuracy > 0) scene.params.simulation.accuracy = a.accuracy;  // checked in (0, 1)
  if (a.position < 0 || a.position >= static_cast<int>(scene.sequence.size()))
    throw vahf::InputError("--position", "", std::to_string(a.position),
                           "must be 0 to " + std::to_string(scene.sequence.size() - 1) +
                               ": the scene's sequence has " +
                               std::to_string(scene.sequence.size()) + " parts");
  vahf::sim::TrialOptions options;
  options.sequence_position = a.position;
  options.record_trace = !a.trace.empty();
  if (a.sample != 0 && !(a.sample > 0 && a.sample <= scene.params.simulation.time_limit))
    throw vahf::InputError("--sample", "", fmt::format("{}", a.sample),
                           "must be > 0 s and at most the scene's time_limit");
  if (a.sample > 0 && a.trace.empty())
    throw vahf::InputError("--sample", "", fmt::format("{}", a.sample),
                           "needs --trace FILE to write the rows to");
  if (a.sample > 0 && scene.params.simulation.time_limit / a.sample > 1e7)
    throw vahf::InputError("--sample", "", fmt::format("{}", a.sample),
                           "at most 1e7 rows over the time limit");
  options.sample_interval = a.sample;
  const vahf::sim::TrialResult r = vahf::sim::RunTrial(scene, {a.seed, a.trial}, options);
  if (!a.trace.empty()) vahf::WriteFileAtomically(a.trace, vahf::sim::TraceCsv(r));
  std::fputs(r.BriefReport().c_str(), stdout);
  if (!a.trace.empty())
    std::printf("trace: %s (%zu decision rows, %zu sample rows)\n", a.trace.c_str(),
                r.trace.size(), r.samples.size());
  if (r.status == vahf::sim::Status::kCompleted) return 0;
  // Anything else is not what a trial is for: say so on one line, exit 1.
  std::string detail = r.detail;
  std::replace(detail.begin(), detail.end(), '\n', ' ');  // Simbody's texts span lines
  std::fprintf(stderr, "vahf: trial ended %s: %s\n", vahf::sim::StatusName(r.status),
               detail.c_str());
  return 1;
}

struct RunArgs {
  std::string experiment;
  std::string overrides;
  std::uint64_t seed = 0;
  bool seed_given = false;
  int trials = 0;
  int threads = 1;
  std::string out;
};

// The files a run against a lab dataset read besides the experiment file:
// the scene, the dataset's manifest and files, the override file.
std::vector<std::string> LabRunInputs(const vahf::scene::ExperimentFile& file,
                                      const vahf::data::LabDataset& lab) {
  std::vector<std::string> inputs = {file.scene_path, lab.file};
  for (const std::string& f : {lab.trials_file, lab.segments_file, lab.summaries_file})
    if (!f.empty()) inputs.push_back(lab.folder + "/" + f);
  for (const auto& t : lab.tracks) inputs.push_back(t.file);
  if (!file.overrides_path.empty()) inputs.push_back(file.overrides_path);
  return inputs;
}

// Writes the output directory of a run against a lab dataset (calibrate,
// compare): the header from the experiment file and the dataset, the one
// section; says on stderr which plots failed.
vahf::report::RunOutput WriteLabRun(const vahf::scene::ExperimentFile& file,
                                    const vahf::data::LabDataset& lab, std::uint64_t seed,
                                    int trials, const std::string& cycles,
                                    const vahf::report::Section& section,
                                    vahf::report::OutputDirectory& directory,
                                    const vahf::report::RunInfo& info) {
  vahf::report::RunHeader h;
  h.file = &file;
  h.first = &file;
  h.seed = seed;
  h.trials = trials;
  h.cycles_per_condition = std::to_string(trials) + cycles;
  h.integration = vahf::report::IntegrationText(file.scene.params);
  h.inputs = LabRunInputs(file, lab);
  const vahf::report::RunOutput written =
      vahf::report::WriteSections(h, {section}, directory, info);
  for (const std::string& failure : written.failed_plots)
    std::fprintf(stderr, "vahf: error: plot not rendered (results kept): %s\n",
                 failure.c_str());
  return written;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A comparison: the lab dataset, the virtual design, its output directory.
int RunComparison(const vahf::scene::ExperimentFile& file,
                  const vahf::experiment::RunSettings& settings, const RunArgs& a,
                  vahf::report::OutputDirectory& directory) {
  const vahf::data::LabDataset lab = vahf::data::LoadLabDataset(file.comparison.lab_path);
  const int trials = settings.trials > 0 ? settings.trials : file.trials;
  vahf::experiment::RunnerOptions options;
  options.threads = settings.threads;
  options.label = file.name + " (compare)";
  options.unit = "cycles";
  vahf::experiment::RunnerOptions pilot_options = options;
  pilot_options.label = file.name + " (compare, fatigue pilot)";
  const auto start = std::chrono::steady_clock::now();
  const vahf::compare::ComparisonResult result = vahf::compare::Compare(
      file.scene, lab, file.comparison, file.file, settings.seed, trials, options,
      pilot_options);
  const vahf::report::RunInfo info{a.threads, SecondsSince(start)};
  const vahf::report::RunOutput written = WriteLabRun(
      file, lab, settings.seed, trials,
      result.fatigue.run.conditions.empty() ? " per lab operator"
      : result.run.conditions.empty()       ? " per segment"
                                            : " per lab operator and per segment",
      vahf::report::ComparisonSection(file, lab, result, trials), directory, info);
  for (const auto& q : result.quantities)
    std::printf("%s: %s\n", q.target.label.c_str(), q.verdict.c_str());
  std::printf("%s: compare, seed %llu, %.1f s on %d thread(s)\nresults digest %s\n"
              "report: %s/report.md\n",
              file.name.c_str(), static_cast<unsigned long long>(settings.seed),
              info.wall_seconds, a.threads, written.results_digest.c_str(),
              directory.path().c_str());
  return written.failed_plots.empty() ? 0 : 1;
}

// A calibration: the lab dataset, Ceres' fit with a line per design
// evaluation, and its output directory with calibrated.json.
int RunCalibration(const vahf::scene::ExperimentFile& file,
                   const vahf::experiment::RunSettings& settings, const RunArgs& a,
                   vahf::report::OutputDirectory& directory) {
  const vahf::data::LabDataset lab = vahf::data::LoadLabDataset(file.calibration.lab_path);
  const int trials = settings.trials > 0 ? settings.trials : file.trials;
  vahf::experiment::RunnerOptions options;
  options.threads = settings.threads;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<vahf::calibrate::CalibrationResult> stages = vahf::calibrate::Calibrate(
      file.scene, lab, file.calibration, file.file, settings.seed, trials, options,
      [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
  const vahf::report::RunInfo info{a.threads, SecondsSince(start)};
  const vahf::report::RunOutput written = WriteLabRun(
      file, lab, settings.seed, trials, " per lab operator and parameter vector",
      vahf::report::CalibrationSection(file, lab, stages), directory, info);
  int evaluations = 0;
  for (const auto& r : stages) {
    evaluations += r.evaluations;
    for (const auto& p : r.parameters)
      std::printf("%s = %.6g, standard error %.3g, 95 %% interval [%.6g, %.6g]\n",
                  p.name.c_str(), p.estimate, p.standard_error, p.ci.lower, p.ci.upper);
  }
  std::printf("%s: calibrate, seed %llu, %.1f s on %d thread(s), %d evaluations\n"
              "results digest %s\nreport: %s/report.md\noverrides: %s/%s\n",
              file.name.c_str(), static_cast<unsigned long long>(settings.seed),
              info.wall_seconds, a.threads, evaluations,
              written.results_digest.c_str(), directory.path().c_str(),
              directory.path().c_str(), vahf::report::kOverridesFile);
  return written.failed_plots.empty() ? 0 : 1;
}

int Run(const RunArgs& a) {
  vahf::scene::ExperimentFile file = vahf::scene::LoadExperiment(a.experiment);
  if (!a.overrides.empty())
    vahf::scene::ApplyOverrides(vahf::scene::LoadOverrides(a.overrides), &file);
  vahf::experiment::RunSettings settings;
  settings.seed = a.seed_given ? a.seed : file.seed;
  settings.trials = a.trials;
  settings.threads = a.threads;
  const std::string out =
      a.out.empty() ? "runs/" + file.name + "-seed" + std::to_string(settings.seed) : a.out;
  // Checked and staged before any simulation: a refused path costs nothing.
  vahf::report::OutputDirectory directory(out);
  vahf::experiment::InstallInterruptHandler();
  if (file.kind == "calibrate") return RunCalibration(file, settings, a, directory);
  if (file.kind == "compare") return RunComparison(file, settings, a, directory);
  const auto start = std::chrono::steady_clock::now();
  const vahf::experiment::ExperimentRun run = vahf::experiment::RunExperiment(file, settings);
  vahf::report::RunInfo info;
  info.threads = a.threads;
  info.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const vahf::report::RunOutput written = vahf::report::WriteRunOutput(run, directory, info);
  const std::string& digest = written.results_digest;
  std::printf("%s: %s, seed %llu, %.1f s on %d thread(s)\nresults digest %s\nreport: %s/report.md\n",
              file.name.c_str(), file.kind.c_str(),
              static_cast<unsigned long long>(settings.seed), info.wall_seconds, a.threads,
              digest.c_str(), out.c_str());
  for (const std::string& failure : written.failed_plots)
    std::fprintf(stderr, "vahf: error: plot not rendered (results kept): %s\n",
                 failure.c_str());
  return written.failed_plots.empty() ? 0 : 1;
}

struct SynthesizeArgs {
  std::string generator;
  std::string out;
  int threads = 1;
};

int Synthesize(const SynthesizeArgs& a) {
  const vahf::calibrate::SyntheticLabSpec spec = vahf::calibrate::LoadSyntheticLabSpec(a.generator);
  vahf::experiment::RunnerOptions options;
  options.threads = a.threads;
  options.label = spec.name + " (synthetic lab)";
  options.unit = "cycles";
  vahf::experiment::InstallInterruptHandler();
  const vahf::data::LabDataset lab = vahf::calibrate::GenerateSyntheticLab(spec, options);
  vahf::data::WriteLabDataset(lab, a.out);
  std::printf("%s: %zu trials of %zu operator(s) written to %s/dataset.json\n",
              spec.name.c_str(), lab.trials.size(), spec.operators.size(), a.out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "vahf: a deterministic, seeded validation harness for physics-based virtual "
      "assembly with human factors"};
  app.set_version_flag("--version", "vahf 0.1.0");
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success; 1 a failure of the computation, stated on stderr (trial: the "
      "trial did not complete); 2 bad input (a file, a value or an option), one line; 130 "
      "interrupted.");

  // Command-line integers, read strictly: decimal digits only, from 0 to
  // `max`, rewritten in canonical form for CLI11's own conversion (CLI11 2.1
  // reads them with strtoull(text, 0): "-1" would wrap to 2^64 - 1, "010" be
  // octal 8 and "0x10" hexadecimal).
  const auto decimal = [](std::uint64_t max) {
    return CLI::Validator(
        [max](std::string& text) {
          std::uint64_t v = 0;
          const char* end = text.data() + text.size();
          const auto [stop, error] = std::from_chars(text.data(), end, v);
          if (text.empty() || error != std::errc() || stop != end || v > max)
            return fmt::format("must be a decimal integer from 0 to {}, not '{}'", max, text);
          text = std::to_string(v);
          return std::string();
        },
        "", "decimal");
  };
  constexpr std::uint64_t kMaxU64 = std::numeric_limits<std::uint64_t>::max();

  std::string check_path;
  CLI::App* check = app.add_subcommand(
      "check", "Validate a scene, experiment or lab dataset file and print what it holds");
  check
      ->add_option("FILE", check_path,
                   "scene, experiment or lab dataset (its dataset.json) JSON file")
      ->required();

  std::string table_path = "reference/paper/table1.json";
  CLI::App* reference = app.add_subcommand(
      "reference", "Check the paper's Table 1 against Eqs. 2, 3 and 6, side by side");
  reference->add_option("--table", table_path, "Table 1 as JSON")->capture_default_str();

  TrialArgs trial_args;
  CLI::App* trial = app.add_subcommand(
      "trial", "Run one seeded trial of a scene's assembling part and print its summary");
  trial->add_option("SCENE", trial_args.scene, "scene JSON file")->required();
  trial->footer(
      "Exit status: 0 the trial completed; 1 it ended otherwise (timeout, exhausted, "
      "unreachable, jammed, numerical_failure): its summary is printed and its trace written, "
      "then 'vahf: trial ended STATUS: DETAIL' on stderr; 2 bad input, one line.");
  trial->add_option("--seed", trial_args.seed, "experiment seed (the stream key)")
      ->required()
      ->transform(decimal(kMaxU64));
  trial->add_option("--trial", trial_args.trial, "trial index (the stream key)")
      ->capture_default_str()
      ->transform(decimal(kMaxU64));
  trial
      ->add_option("--position", trial_args.position,
                   "which entry of the scene's sequence to assemble (0 = first)")
      ->capture_default_str();
  trial
      ->add_option("--integrator", trial_args.integrator,
                   "override simulation/integrator")
      ->check(CLI::IsMember(vahf::scene::IntegratorNames()));
  trial
      ->add_option("--accuracy", trial_args.accuracy,
                   "override simulation/accuracy, in (0, 1) as its rule")
      ->check(CLI::Validator(
          [](std::string& text) {
            // Simbody asserts 0 < accuracy < 1; nan passes CLI::PositiveNumber.
            double x = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, x);
            if (error != std::errc() || stop != end || !(x > 0 && x < 1))
              return fmt::format("must be a number in (0, 1), not '{}'", text);
            return std::string();
          },
          "", "open unit interval"));
  trial->add_option("--trace", trial_args.trace,
                    "write one CSV row per decision instant to this file");
  trial
      ->add_option("--sample", trial_args.sample,
                   "with --trace: also a row every DT s of simulated time (pose, velocities, "
                   "forces, penetration), interpolated, so the trajectory is unchanged")
      ->option_text("DT");

  RunArgs run_args;
  CLI::App* run = app.add_subcommand(
      "run", "Run an experiment file and write its output directory (report.md, CSV "
             "tables, summary.json, manifest.json, plots)");
  run->add_option("EXPERIMENT", run_args.experiment, "experiment JSON file")->required();
  run->add_option("--seed", run_args.seed, "override the experiment's seed")
      ->transform(decimal(kMaxU64))
      ->each([&](const std::string&) { run_args.seed_given = true; });
  run->add_option("--trials", run_args.trials,
                  "override the cycles per condition (every experiment of a paper run)")
      ->transform(decimal(10'000'000))
      ->check(CLI::Range(1, 10'000'000));
  run->add_option("--threads", run_args.threads, "worker threads (results do not depend on it)")
      ->transform(decimal(1024))
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  run->add_option("--out", run_args.out,
                  "output directory (default runs/NAME-seedSEED); replaced whole, only if it "
                  "is empty or a previous vahf output");

  run->add_option("--overrides", run_args.overrides,
                  "parameter-override file (vahf-overrides/1, e.g. a calibration's "
                  "calibrated.json) applied to every scene the experiment runs");

  SynthesizeArgs synth_args;
  CLI::App* synthesize = app.add_subcommand(
      "synthesize", "Make a synthetic lab dataset: the model at stated parameter values plays "
                    "the lab (docs/calibration.md)");
  synthesize->add_option("GENERATOR", synth_args.generator, "generator JSON file (vahf-synthetic/1)")
      ->required();
  synthesize->add_option("--out", synth_args.out, "folder for dataset.json and trials.csv")
      ->required();
  synthesize->add_option("--threads", synth_args.threads, "worker threads (results do not depend on it)")
      ->transform(decimal(1024))
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();

  CLI::App* params = app.add_subcommand(
      "params", "Print every model parameter with its unit, rule and default (Markdown)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, as every input error (CLI11's exit() adds a second).
    std::fprintf(stderr, "vahf: error: %s\n", e.what());
    return vahf::kExitInputError;
  }

  try {
    if (*check) return Check(check_path);
    if (*reference) return Reference(table_path);
    if (*trial) return Trial(trial_args);
    if (*run) return Run(run_args);
    if (*synthesize) return Synthesize(synth_args);
    if (*params) {
      std::fputs(vahf::scene::ParameterTableMarkdown().c_str(), stdout);
      return 0;
    }
  } catch (const vahf::InputError& e) {
    std::fprintf(stderr, "vahf: error: %s\n", e.what());
    return vahf::kExitInputError;
  } catch (const vahf::experiment::Interrupted& e) {
    std::fprintf(stderr, "vahf: interrupted: %s; no output was written\n", e.what());
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vahf: error: %s\n", e.what());
    return 1;
  }
  return 1;
}
