// An experiment file names a kind of experiment, the scene it runs on, the seed
// and the number of trials (docs/scene-format.md, "Experiment files").
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene.h"

namespace vahf::scene {

inline constexpr const char* kExperimentFormat = "vahf-experiment/1";
// A lab dataset's manifest (data/lab_dataset.h reads it; named here so that
// FormatOf can tell it without the data layer).
inline constexpr const char* kLabFormat = "vahf-lab/1";
// A parameter-override file (overrides.h) and a synthetic lab generator
// (calibrate/synthetic_lab.h): named here so that FormatOf tells every vahf
// file apart.
inline constexpr const char* kOverridesFormat = "vahf-overrides/1";
inline constexpr const char* kSyntheticFormat = "vahf-synthetic/1";

// An operator of an assembly_time experiment: the scene's operator with this
// stature and arm length (standing where the scene's operator stands).
struct OperatorEntry {
  std::string name;
  std::string sex;        // "male" or "female"
  double height = 0;      // m
  double arm_length = 0;  // m
  std::string source;     // where the dimensions come from
};

// A working condition of a human_factors_groups experiment: its own scene.
struct ConditionEntry {
  std::string name;
  std::string scene_path;
  Scene scene;
};

// One hour of continuous cycles in segments (fatigue, paper Sec. 5.4).
struct FatigueDesign {
  double duration_min = 60.0;
  int segments = 4;
  int pilot_cycles = 0;  // cycles from A = 0 that measure the work rate; 0: `trials`
};

// A set of parameter overrides of a precision experiment, as written:
// "group/key" (ParamName) -> value, in name order.
struct PrecisionSetting {
  std::string label;    // "RungeKuttaMerson 1e-4", "visibility/grid 16"
  std::string pointer;  // where the file holds it: "/settings/3", "/reference"
  std::vector<std::pair<std::string, nlohmann::json>> overrides;
  // Exactly simulation/accuracy, with or without simulation/integrator: a point
  // of its integrator's work-precision line.
  bool AccuracyOnly() const;
};

// A scene of a precision experiment with the parameters of each setting
// applied on top of its own, each validated as the scene loader does.
struct PrecisionScene {
  std::string path;
  Scene scene;      // as its file gives it
  int trials = 0;   // > 0: this scene's cycles per setting instead of `trials`
  Scene reference;  // scene + the reference's overrides
  std::vector<Scene> settings;  // scene + each setting's overrides, in file order
};

// Error against run time (docs/experiments.md, "precision").
struct PrecisionDesign {
  std::vector<PrecisionScene> scenes;
  PrecisionSetting reference;
  std::vector<PrecisionSetting> settings;
  // Cycles per condition of the experiment that will use the recommended
  // setting: its Monte Carlo noise is the reference's standard deviation over
  // sqrt(noise_trials). Default: the most of any paper experiment (fatigue's 12).
  int noise_trials = kDefaultNoiseTrials;
  static constexpr int kDefaultNoiseTrials = 12;
};

// A parameter a calibration fits: its name in the parameter table
// ("guidance/kappa", a real-valued one), where the search starts and the
// bounds it stays within (docs/calibration.md).
struct FitParameter {
  std::string name;
  double start = 0, lower = 0, upper = 0;
  std::string pointer;  // where the experiment file states it
};

// A lab summary a calibration fits (calibrate/targets.h): a quantity of one
// part ("all": whole cycles), over all the lab's operators or each one's.
struct FitTarget {
  std::string quantity;      // "assembly_time" or "success_rate"
  std::string part;          // a part of the scene's sequence, or "all"
  bool by_operator = false;  // one target per lab operator instead of one over all
  std::string pointer;       // where the experiment file states it
  // compare: the equivalence margin, in the quantity's unit (s, or 1 for a
  // rate): virtual and lab agree when their difference is shown within it.
  double margin = 0;
  // A segment of the hour of work (1-based; 0: none): the lab's value of that
  // segment, against a fatigue design's (FatigueDesign of the same file).
  int segment = 0;
  // The lab's condition (series) to read, e.g. "real"; empty: any.
  std::string condition;
};

// A virtual design against a lab dataset, quantity by quantity
// (compare/comparison.h).
struct ComparisonDesign {
  std::string lab_path;  // the lab dataset's manifest
  std::vector<FitTarget> quantities;
  // The hour of work that segment quantities are read from (the file's
  // "fatigue", as the fatigue kind reads it).
  FatigueDesign fatigue;
};

// One stage of a calibration: parameters fitted to targets by a solver.
struct CalibrationStage {
  std::string name;     // the file's stage name; "" for a file of one stage
  std::string pointer;  // where the file states it ("" for a file of one stage)
  // "levenberg_marquardt" (Ceres) or "golden_section" (one parameter: GSL's bracketed
  // golden-section minimisation of the same cost, for objectives that are piecewise
  // constant in the parameter; Ceres then gives the covariance).
  std::string solver = "levenberg_marquardt";
  std::vector<FitParameter> parameters;
  std::vector<FitTarget> targets;
};

// Ceres least squares of parameters to a lab dataset's summaries
// (calibrate/calibration.h), in stages: each stage starts from the scene with
// every earlier stage's estimates (a sequential calibration).
struct CalibrationDesign {
  std::string lab_path;                  // the lab dataset's manifest
  std::vector<CalibrationStage> stages;  // at least one
  // Robust loss on the whitened residuals: "huber", "cauchy" or "none"; its
  // scale in standard deviations (residuals beyond it are down-weighted).
  std::string loss = "huber";
  double loss_scale = 3.0;
  double relative_step = 0.05;  // of each parameter's value, central differences
  int max_iterations =
      30;  // Levenberg-Marquardt (or golden-section) iterations per round
  // golden_section: the search stops when the bracket is narrower than this fraction
  // of the estimate.
  double tolerance = 0.02;
  // The hour of work that segment targets are read from (the file's
  // "fatigue", as the fatigue kind reads it).
  FatigueDesign fatigue;
};

// A case of a stability experiment (docs/experiments.md, "stability"): a
// scene, changed by a patch of its document and by parameter overrides, run
// at one position of its sequence under each integrator, with the outcome
// classes the file expects of it.
struct StabilityCase {
  std::string name;
  std::string pointer;     // where the file states it: "/cases/3"
  std::string scene_path;  // resolved against the experiment file's folder
  int position = 0;        // the entry of the scene's sequence to run
  // JSON pointer (RFC 6901) into the scene document -> the value that
  // replaces what is there, applied before the scene is read; each pointer
  // names a value the document already holds.
  std::vector<std::pair<std::string, nlohmann::json>> patch;
  // "group/key" -> value, on top of the (patched) scene's own parameters.
  std::vector<std::pair<std::string, nlohmann::json>> overrides;
  std::vector<std::string> integrators;  // the case's own, else the file's
  int seeds = 1;                         // trials per integrator: stream keys 0..seeds-1
  // Outcome classes: trial status names (sim/trial_result.h), checked against
  // them by the kind's check (kinds/stability_kind.cc); "/cases/3/expect/1".
  std::vector<std::string> expect;
  std::vector<std::string> expect_pointers;
  // The scene patched and overridden, once per integrator (in `integrators`
  // order), each validated as the scene loader does.
  std::vector<Scene> scenes;
};

// Stiff and extreme cases across integrators (docs/experiments.md,
// "stability").
struct StabilityDesign {
  std::vector<std::string> integrators;  // the default of every case
  std::vector<StabilityCase> cases;
};

// "RungeKuttaMerson 1e-4" for an integrator and accuracy, then "group/key
// value" for each other override, joined by ", " ("CVODE 1e-4,
// simulation/velocity_time_scale 0.1"); "scene parameters" for no overrides.
// Numbers in their shortest exact form, powers of ten as 1e-4.
std::string SettingLabel(
    const std::vector<std::pair<std::string, nlohmann::json>>& overrides);

struct ExperimentFile {
  std::string file;
  std::string name;
  std::string description;
  std::string kind;
  std::string scene_path;  // resolved against the experiment file's folder
  Scene scene;
  std::uint64_t seed = 1;
  int trials = 1;  // cycles per condition (operator, working condition, segment)

  std::vector<OperatorEntry> operators;    // assembly_time; empty: the scene's
  std::vector<ConditionEntry> conditions;  // human_factors_groups
  // human_factors_groups: the paper's instants (s) in its whole assembly of
  // `paper_cycle_s` seconds (Sec. 5.3: 3, 6, ..., 15 s of about 16 s); each
  // is sampled at the same fraction of a virtual cycle.
  std::vector<double> instants_s;
  double paper_cycle_s = 16.0;
  // table1: the paper's Table 1 as JSON (reference/paper/table1.json), shown
  // beside the virtual values; empty: no comparison.
  std::string paper_table_path;
  FatigueDesign fatigue;  // fatigue
  // precision: the scenes, reference and settings; `scene_path` and `scene`
  // are its first scene's (the manifest's "scene").
  PrecisionDesign precision;
  CalibrationDesign calibration;  // calibrate
  // stability: its cases; `scene_path` and `scene` are its first case's.
  StabilityDesign stability;
  ComparisonDesign comparison;  // compare
  // The parameter-override file applied to every scene (overrides.h), if any.
  std::string overrides_path;
  std::vector<ExperimentFile> experiments;  // paper: the experiments it runs
};

// What `vahf check` prints about a precision experiment: its scenes with
// their cycles, the reference and every setting with its overrides.
std::string DescribePrecision(const ExperimentFile& file);

// A file named in `node`, relative to `experiment_path`'s folder (or
// absolute); an InputError at the node when no such file exists. `what`
// names the kind of file in the message ("scene").
std::string ResolvePath(const JsonNode& node, const std::string& experiment_path,
                        const char* what);

// Operators as an experiment file lists them (assembly_time's "operators":
// name, sex, height, arm_length, source), checked against the scene's reach
// rule; names unique.
std::vector<OperatorEntry> ReadOperators(const JsonNode& node, const Scene& scene);

// Reading an experiment file (kinds/kind.h parses it: the common fields, then
// the keys of its kind through the kind's registered reader). Each reader
// below takes the file's root object and its path and fills its part of `e`;
// errors name whichever file holds the fault.

// format, name, description, kind (one of `kinds`), seed and trials.
ExperimentFile ReadExperimentHeader(const JsonNode& root, const std::string& path,
                                    const std::vector<std::string>& kinds);
// "scene": the file it names, loaded.
void ReadExperimentScene(const JsonNode& root, const std::string& path,
                         ExperimentFile* e);
// table1: "paper_table".
void ReadTable1(const JsonNode& root, const std::string& path, ExperimentFile* e);
// assembly_time: "operators".
void ReadAssemblyTime(const JsonNode& root, const std::string& path, ExperimentFile* e);
// human_factors_groups: "conditions", "instants_s", "paper_cycle_s".
void ReadHumanFactorsGroups(const JsonNode& root, const std::string& path,
                            ExperimentFile* e);
// fatigue: "fatigue" (also read by calibrate and compare for segment targets).
void ReadFatigue(const JsonNode& root, const std::string& path, ExperimentFile* e);
// precision: "scenes", "reference", "settings", "noise_trials".
void ReadPrecision(const JsonNode& root, const std::string& path, ExperimentFile* e);
// calibrate: "lab", "fatigue", the fit's parameters, targets, stages and settings.
void ReadCalibration(const JsonNode& root, const std::string& path, ExperimentFile* e);
// compare: "lab", "fatigue", "quantities".
void ReadComparison(const JsonNode& root, const std::string& path, ExperimentFile* e);
// stability: "integrators", "cases".
void ReadStability(const JsonNode& root, const std::string& path, ExperimentFile* e);

// What `vahf check` prints about a stability experiment: every case with its
// scene, patch, overrides, integrators, seeds and expected outcomes.
std::string DescribeStability(const ExperimentFile& file);

// "scene", "experiment", "lab", "overrides" or "synthetic" by the document's "format"
// field; an InputError naming `file` otherwise.
std::string FormatOf(const nlohmann::json& document, const std::string& file);
// The same, reading the file.
std::string FileFormatOf(const std::string& path);

}  // namespace vahf::scene
