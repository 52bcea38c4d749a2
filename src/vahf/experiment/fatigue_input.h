// The input of a fatigue experiment (docs/experiments.md, "fatigue"): the hour
// of work in segments.
#pragma once

#include <string>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/shared_inputs.h"

namespace vahf::experiment {

struct FatigueInput : scene::KindInputOf<FatigueInput> {
  scene::FatigueDesign fatigue;
};

// fatigue: "fatigue".
void ReadFatigueExperiment(const scene::JsonNode& root, const std::string& path,
                           scene::ExperimentFile* e);

}  // namespace vahf::experiment
