// The input of a precision experiment (docs/experiments.md, "precision"):
// scenes, a reference setting and the settings compared with it, as its
// experiment file states them and its reader reads them.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene.h"

namespace vahf::experiment {

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
  scene::Scene scene;      // as its file gives it
  int trials = 0;          // > 0: this scene's cycles per setting instead of `trials`
  scene::Scene reference;  // scene + the reference's overrides
  std::vector<scene::Scene> settings;  // scene + each setting's overrides, in file order
};

// Error against run time (docs/experiments.md, "precision").
struct PrecisionDesign : scene::KindInputOf<PrecisionDesign> {
  std::vector<PrecisionScene> scenes;
  PrecisionSetting reference;
  std::vector<PrecisionSetting> settings;
  // Cycles per condition of the experiment that will use the recommended
  // setting: its Monte Carlo noise is the reference's standard deviation over
  // sqrt(noise_trials). Default: the most of any paper experiment (fatigue's 12).
  int noise_trials = kDefaultNoiseTrials;
  static constexpr int kDefaultNoiseTrials = 12;

  // Each scene gets the override file; its reference and settings too, but
  // for what each sets itself. The file's scene becomes the first scene's.
  void ApplyOverrides(const scene::ParameterOverrides& o,
                      scene::ExperimentFile* file) override;
  std::vector<std::string> InputFiles() const override;  // the scenes
};

// "RungeKuttaMerson 1e-4" for an integrator and accuracy, then "group/key
// value" for each other override, joined by ", " ("CVODE 1e-4,
// simulation/velocity_time_scale 0.1"); "scene parameters" for no overrides.
// Numbers in their shortest exact form, powers of ten as 1e-4.
std::string SettingLabel(
    const std::vector<std::pair<std::string, nlohmann::json>>& overrides);

// What `vahf check` prints about a precision experiment: its scenes with
// their cycles, the reference and every setting with its overrides.
std::string DescribePrecision(const scene::ExperimentFile& file);

// precision: "scenes", "reference", "settings", "noise_trials"; the file's
// scene is its first scene.
void ReadPrecision(const scene::JsonNode& root, const std::string& path,
                   scene::ExperimentFile* e);

}  // namespace vahf::experiment
