// The input of a paper experiment (docs/experiments.md, "paper"): the
// experiments it runs into one output directory, each read from its own file.
#pragma once

#include <string>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"

namespace vahf::kinds {

struct PaperInput : scene::KindInputOf<PaperInput> {
  std::vector<scene::ExperimentFile> experiments;

  // Each experiment it lists gets the override file (as a run of it would).
  void ApplyOverrides(const scene::ParameterOverrides& o,
                      scene::ExperimentFile* file) override;
};

// paper: "experiments", each a design of cycles (registry.cc's ParseExperiment
// reads them); they name their scenes.
void ParsePaper(const scene::JsonNode& root, const std::string& path,
                scene::ExperimentFile* e);

}  // namespace vahf::kinds
