// The input of a stability experiment (docs/experiments.md, "stability"): its
// cases, as its experiment file states them and its reader reads them.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene.h"

namespace vahf::experiment {

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
  std::vector<scene::Scene> scenes;
};

// Stiff and extreme cases across integrators (docs/experiments.md,
// "stability").
struct StabilityDesign : scene::KindInputOf<StabilityDesign> {
  std::vector<std::string> integrators;  // the default of every case
  std::vector<StabilityCase> cases;

  // Each case's scenes get the override file but for what the case sets
  // itself and its integrator; the file's scene becomes the first case's.
  void ApplyOverrides(const scene::ParameterOverrides& o,
                      scene::ExperimentFile* file) override;
};

// stability: "integrators", "cases"; the file's scene is its first case's.
void ReadStability(const scene::JsonNode& root, const std::string& path,
                   scene::ExperimentFile* e);

// What `vahf check` prints about a stability experiment: every case with its
// scene, patch, overrides, integrators, seeds and expected outcomes.
std::string DescribeStability(const scene::ExperimentFile& file);

}  // namespace vahf::experiment
