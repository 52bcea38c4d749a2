// An experiment file names a kind of experiment, the scene it runs on, the seed
// and the number of trials (docs/scene-format.md, "Experiment files").
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vahf/scene/scene.h"

namespace vahf::scene {

inline constexpr const char* kExperimentFormat = "vahf-experiment/1";

// The experiment kinds of DESIGN.md, "Experiments".
const std::vector<std::string>& ExperimentKinds();

struct ExperimentFile {
  std::string file;
  std::string name;
  std::string kind;
  std::string scene_path;  // resolved against the experiment file's folder
  Scene scene;
  std::uint64_t seed = 1;
  int trials = 1;
};

// Loads the experiment and the scene it names; errors name whichever file
// holds the fault.
ExperimentFile LoadExperiment(const std::string& path);
// The same for an already parsed document read from `path`.
ExperimentFile ParseExperiment(const nlohmann::json& document, const std::string& path);

// "scene" or "experiment" by the document's "format" field; an InputError
// naming `file` otherwise.
std::string FormatOf(const nlohmann::json& document, const std::string& file);
// The same, reading the file.
std::string FileFormatOf(const std::string& path);

}  // namespace vahf::scene
