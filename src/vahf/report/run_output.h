// Writes a run's output directory (docs/outputs.md): the sections' tidy CSV
// tables, summary.json, the manifest with the results digest, report.md and
// the plots, staged and committed whole (output_directory.h).
#pragma once

#include <string>
#include <vector>

#include "vahf/experiment/design.h"
#include "vahf/report/output_directory.h"

namespace vahf::report {

struct RunInfo {
  int threads = 1;
  double wall_seconds = 0;  // in report.md only, never in a result file
};

struct RunOutput {
  std::string results_digest;
  // Plots gnuplot could not render, with its message. A failed plot never
  // costs the results: the output is committed, report.md says which figure
  // is missing and why, and the caller reports the failure.
  std::vector<std::string> failed_plots;
};

// Writes into `out` (created before the run, so that a refused path costs no
// simulation) and commits it.
RunOutput WriteRunOutput(const experiment::ExperimentRun& run, OutputDirectory& out,
                         const RunInfo& info);

}  // namespace vahf::report
