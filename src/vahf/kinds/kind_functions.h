// The functions each kind registers (kinds/registry.cc), by the file that
// holds them: design_kinds.cc (the designs of cycles and the paper run),
// calibrate_kind.cc, compare_kind.cc, stability_kind.cc.
#pragma once

#include <string>

#include "vahf/kinds/kind.h"

namespace vahf::kinds {

// design_kinds.cc
std::string CheckOneScene(
    const scene::ExperimentFile& file);  // table1, assembly_time, fatigue
std::string CheckGroups(const scene::ExperimentFile& file);
std::string CheckPrecision(const scene::ExperimentFile& file);
std::string CheckPaper(const scene::ExperimentFile& file);
experiment::ExperimentRun PaperRun(const scene::ExperimentFile& file,
                                   const experiment::RunSettings& settings);

// calibrate_kind.cc
std::string CheckCalibration(const scene::ExperimentFile& file);
int RunCalibration(const scene::ExperimentFile& file, const RunContext& context);

// compare_kind.cc
std::string CheckComparison(const scene::ExperimentFile& file);
int RunComparison(const scene::ExperimentFile& file, const RunContext& context);

// stability_kind.cc
std::string CheckStability(const scene::ExperimentFile& file);
int RunStability(const scene::ExperimentFile& file, const RunContext& context);

}  // namespace vahf::kinds
