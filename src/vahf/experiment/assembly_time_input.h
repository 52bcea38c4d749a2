// The input of an assembly_time experiment (docs/experiments.md,
// "assembly_time"): the operators it runs the scene with.
#pragma once

#include <string>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/shared_inputs.h"

namespace vahf::experiment {

struct AssemblyTimeInput : scene::KindInputOf<AssemblyTimeInput> {
  std::vector<scene::OperatorEntry> operators;  // empty: the scene's

  // The scene runs once per listed operator: the reach rule must hold for
  // each of them under the override file, as ReadOperators checks at load.
  void ApplyOverrides(const scene::ParameterOverrides& o,
                      scene::ExperimentFile* file) override;
};

// assembly_time: "operators".
void ReadAssemblyTime(const scene::JsonNode& root, const std::string& path,
                      scene::ExperimentFile* e);

}  // namespace vahf::experiment
