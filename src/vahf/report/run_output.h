// Writes a run's output directory (docs/outputs.md): the sections' tidy CSV
// tables, summary.json, the manifest with the results digest, report.md and
// the plots, staged and committed whole (output_directory.h).
#pragma once

#include <string>

#include "vahf/experiment/design.h"

namespace vahf::report {

struct RunInfo {
  int threads = 1;
  double wall_seconds = 0;  // in report.md only, never in a result file
};

// Returns the results digest. Plots that gnuplot cannot render are a
// PlotError: nothing is committed then.
std::string WriteRunOutput(const experiment::ExperimentRun& run, const std::string& path,
                           const RunInfo& info);

}  // namespace vahf::report
