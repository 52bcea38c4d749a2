// The input of a human_factors_groups experiment (docs/experiments.md,
// "human_factors_groups"): the working conditions, each its own scene, and the
// paper's instants.
#pragma once

#include <string>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene.h"

namespace vahf::experiment {

// A working condition of a human_factors_groups experiment: its own scene.
struct ConditionEntry {
  std::string name;
  std::string scene_path;
  scene::Scene scene;
};

struct GroupsInput : scene::KindInputOf<GroupsInput> {
  std::vector<ConditionEntry> conditions;
  // The paper's instants (s) in its whole assembly of `paper_cycle_s` seconds
  // (Sec. 5.3: 3, 6, ..., 15 s of about 16 s); each is sampled at the same
  // fraction of a virtual cycle.
  std::vector<double> instants_s;
  double paper_cycle_s = 16.0;

  void ApplyOverrides(const scene::ParameterOverrides& o,
                      scene::ExperimentFile* file) override;  // each condition's scene
  std::vector<std::string> InputFiles() const override;       // the conditions' scenes
};

// human_factors_groups: "conditions", "instants_s", "paper_cycle_s".
void ReadHumanFactorsGroups(const scene::JsonNode& root, const std::string& path,
                            scene::ExperimentFile* e);

}  // namespace vahf::experiment
