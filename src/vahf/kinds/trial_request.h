// One seeded trial of a scene as `vahf trial` and the Python module's
// vahf.trial run it: the scene file told apart from vahf's other files, the
// parameter overrides applied by the parameter table's rules, the options
// checked, then sim::RunTrial. One implementation for both.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vahf/scene/scene.h"
#include "vahf/sim/trial_result.h"

namespace vahf::kinds {

// Reads a scene file; another vahf file (an experiment, a lab dataset, ...)
// is an InputError naming what it is and the command that takes it.
scene::Scene LoadSceneFile(const std::string& path);

// Parameter overrides: each (GROUP/KEY, value) read by the parameter table's
// rule. An error names `option` (the command's "--set", the module's "set")
// as its file, the parameter as its JSON pointer, the value and the rule.
using ParameterSets = std::vector<std::pair<std::string, nlohmann::json>>;
void SetParameters(const char* option, const ParameterSets& sets, scene::Scene* scene);

// Splits the command's GROUP/KEY=VALUE texts, each VALUE read as JSON (a
// number), else taken as text (a choice's bare name); an InputError for one
// without '='.
ParameterSets SplitParameterSets(const std::vector<std::string>& texts);

struct TrialRequest {
  std::uint64_t seed = 1;
  std::uint64_t trial = 0;
  int position = 0;        // the entry of the scene's sequence to assemble
  std::string integrator;  // empty: the scene's
  std::string accuracy;    // as --accuracy's text; empty: the scene's
  ParameterSets sets;      // applied after integrator and accuracy
  bool record_trace = false;
  double sample = 0;  // s; > 0: also a trace row every `sample` s (needs record_trace)
  // How errors name the options: the command's, or the module's arguments.
  struct Names {
    const char* sets = "--set";
    const char* position = "--position";
    const char* sample = "--sample";
    const char* trace_needed = "needs --trace FILE to write the rows to";
  } names;
};

// Applies the request's integrator, accuracy and sets to `scene` (from file
// `path`), checks position and sample against it, runs the trial.
sim::TrialResult RunTrialRequest(scene::Scene scene, const std::string& path,
                                 const TrialRequest& request);

}  // namespace vahf::kinds
