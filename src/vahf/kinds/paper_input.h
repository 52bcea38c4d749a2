// The input of a paper experiment (docs/experiments.md, "paper"): the
// experiments it runs into one output directory, each read from its own file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vahf/data/handbook.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"

namespace vahf::kinds {

struct PaperInput : scene::KindInputOf<PaperInput> {
  std::vector<scene::ExperimentFile> experiments;
  // "handbooks" (optional): the handbook tables (data/handbooks/) the report
  // sets each part's virtual insertion time beside (report/handbook_section.h).
  struct Handbooks {
    data::BdInsertionTable boothroyd_dewhurst;
    data::MtmPositionTable mtm1_position;
  };
  std::optional<Handbooks> handbooks;

  // Each experiment it lists gets the override file (as a run of it would).
  void ApplyOverrides(const scene::ParameterOverrides& o,
                      scene::ExperimentFile* file) override;
  std::vector<std::string> InputFiles() const override;
};

// paper: "experiments", each a design of cycles (registry.cc's ParseExperiment
// reads them); they name their scenes. Optional "handbooks": {"boothroyd_dewhurst":
// PATH, "mtm1_position": PATH}, each relative to the experiment file's folder
// and read at once (a missing file or a bad row is an InputError naming it).
void ParsePaper(const scene::JsonNode& root, const std::string& path,
                scene::ExperimentFile* e);

}  // namespace vahf::kinds
