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

// The experiment kinds of docs/design.md, "Experiments".
const std::vector<std::string>& ExperimentKinds();

// An operator of an assembly_time experiment: the scene's operator with this
// stature and arm length (standing where the scene's operator stands).
struct OperatorEntry {
  std::string name;
  std::string sex;     // "male" or "female"
  double height = 0;   // m
  double arm_length = 0;  // m
  std::string source;  // where the dimensions come from
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
  FatigueDesign fatigue;                   // fatigue
  std::vector<ExperimentFile> experiments; // paper: the experiments it runs
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
