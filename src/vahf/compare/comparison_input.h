// The input of a compare experiment (docs/calibration.md, "Compare"): the lab
// dataset and the quantities compared with it, as its experiment file states
// them and its reader reads them.
#pragma once

#include <string>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/shared_inputs.h"

namespace vahf::compare {

// A virtual design against a lab dataset, quantity by quantity
// (compare/comparison.h).
struct ComparisonDesign : scene::KindInputOf<ComparisonDesign> {
  std::string lab_path;  // the lab dataset's manifest
  // The lab dataset's files (data::LabDatasetFiles), as CalibrationDesign's.
  std::vector<std::string> InputFiles() const override;
  std::vector<scene::FitTarget> quantities;
  // The hour of work that segment quantities are read from (the file's
  // "fatigue", as the fatigue kind reads it).
  scene::FatigueDesign fatigue;
};

// compare: "lab", "fatigue", "quantities".
void ReadComparison(const scene::JsonNode& root, const std::string& path,
                    scene::ExperimentFile* e);

}  // namespace vahf::compare
