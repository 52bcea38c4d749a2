// The output of a run against a lab dataset (calibrate, compare): its header
// from the experiment file and the dataset, and its one section.
#pragma once

#include <cstdint>
#include <string>

#include "vahf/data/lab_dataset.h"
#include "vahf/kinds/kind.h"
#include "vahf/report/run_output.h"

namespace vahf::kinds {

// Writes the directory: the manifest lists the scene, the dataset's manifest
// and files and the override file besides the experiment file.
report::RunOutput WriteLabRun(const scene::ExperimentFile& file,
                              const data::LabDataset& lab, const RunContext& context,
                              int trials, const std::string& cycles,
                              const report::Section& section,
                              const report::RunInfo& info);

}  // namespace vahf::kinds
