// The report of a stability experiment (docs/experiments.md, "stability"):
// per case and integrator the status against the classes the case expects,
// pass or FAIL, the warnings record, the deepest contact against its bound,
// the steps, and (measured) the CPU seconds and real-time factor.
#pragma once

#include <string>
#include <vector>

#include "vahf/experiment/stability_design.h"
#include "vahf/report/section.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::report {

// "pen 709, retry 9" (the warnings record's counts by kind, in kind order,
// by the short names of the report's legend); "-" when there is none.
std::string CompactWarnings(const Warnings& warnings);

// The names of the cases with a trial that fails (StabilityTrial::failures),
// in file order.
std::vector<std::string> FailedCases(
    const experiment::StabilityDesign& design,
    const std::vector<experiment::StabilityTrial>& trials);

// stability_trials.csv (a row per trial: deterministic), stability_cost.csv
// (measured: CPU, wall, real-time factor), summary.json's "stability" part
// (every case's trials and verdicts, the failed cases), measured.json's
// (per trial CPU and wall), and report.md's table.
Section StabilitySection(const scene::ExperimentFile& file,
                         const std::vector<experiment::StabilityTrial>& trials);

}  // namespace vahf::report
