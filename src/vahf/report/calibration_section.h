// The report of a calibration (docs/calibration.md): the fitted parameters
// with their standard errors and 95 % intervals, each target's lab and
// virtual statistics at the start and at the fit, Ceres' summary, a plot of
// lab against virtual, and the fitted values as a parameter-override file
// (calibrated.json) that `vahf run --overrides` accepts.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vahf/calibrate/calibration.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/report/section.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::report {

inline constexpr const char* kOverridesFile = "calibrated.json";

// {"format": "vahf-overrides/1", "source": ..., "parameters": {"group/key": value}}.
nlohmann::json OverridesJson(const scene::ExperimentFile& file,
                             const std::vector<calibrate::CalibrationResult>& stages);

// One subsection per stage (a file of one stage: one).
Section CalibrationSection(const scene::ExperimentFile& file, const data::LabDataset& lab,
                           const std::vector<calibrate::CalibrationResult>& stages);

}  // namespace vahf::report
