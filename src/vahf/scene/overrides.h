// A parameter-override file (docs/calibration.md, "The loop"): parameter
// values, named as in `vahf params`, that `vahf run --overrides FILE` applies
// to every scene an experiment runs, so that the values a calibration fitted
// (it writes such a file, calibrated.json) can be run and compared.
//
//   {"format": "vahf-overrides/1", "source": "where the values come from",
//    "parameters": {"guidance/kappa": 251.3, "fatigue/a_max": 350000}}
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/scene.h"

namespace vahf::scene {

struct ParameterOverrides {
  std::string file;
  std::string source;
  // "group/key" -> value, in name order (the JSON reader's), each valid by
  // the parameter table's rule.
  std::vector<std::pair<std::string, nlohmann::json>> values;
};

// Reads and checks an override file: one InputError naming the file, the
// pointer, the value and the rule for any fault.
ParameterOverrides LoadOverrides(const std::string& path);

// Sets the values in `scene` and checks the rules that tie parameters
// together; a violation is an InputError naming the override file and the
// scene.
void ApplyOverrides(const ParameterOverrides& overrides, Scene* scene);

// The same, keeping what a kind's setting sets itself (it is what the
// experiment varies): a value named in `own`, or `also_own`, is not set.
void ApplyOverridesExcept(const ParameterOverrides& overrides,
                          const std::vector<std::pair<std::string, nlohmann::json>>& own,
                          const std::string& also_own, Scene* scene);

// The same for every scene an experiment runs: its scene (but for the
// parameters its kind sets itself, KindInput::OwnParameters), then the scenes its
// kind's input holds (KindInput::ApplyOverrides: working conditions, a
// precision experiment's scenes with their reference and settings, a stability
// case's scenes, each experiment a paper run lists).
void ApplyOverrides(const ParameterOverrides& overrides, ExperimentFile* file);

}  // namespace vahf::scene
