// Writes a run's output directory (docs/outputs.md): the sections' tidy CSV
// tables, summary.json, the manifest with the results digest, report.md and
// the plots, staged and committed whole (output_directory.h).
#pragma once

#include <string>
#include <vector>

#include "vahf/experiment/design.h"
#include "vahf/report/output_directory.h"
#include "vahf/report/section.h"

namespace vahf::report {

struct RunInfo {
  int threads = 1;
  double wall_seconds = 0;  // in report.md only, never in a result file
  int trials_option =
      0;          // the --trials given, 0 for the file's (the manifest's invocation)
  int ranks = 1;  // the MPI ranks it was spread over (1: none)
};

struct RunOutput {
  std::string results_digest;
  // Plots gnuplot could not render, with its message. A failed plot never
  // costs the results: the output is committed, report.md says which figure
  // is missing and why, and the caller reports the failure.
  std::vector<std::string> failed_plots;
};

// Writes a design's run with its sections (one per experiment run: the run
// itself, or each part of a paper run, in order) into `out` (created before
// the run, so that a refused path costs no simulation) and commits it.
RunOutput WriteRunOutput(const experiment::ExperimentRun& run,
                         const std::vector<Section>& sections, OutputDirectory& out,
                         const RunInfo& info);

// What an output directory says about a run besides its sections: the
// experiment file, the file whose scene and parameters the manifest records,
// the seed and cycles, and every other file the run read.
struct RunHeader {
  const scene::ExperimentFile* file = nullptr;
  const scene::ExperimentFile* first = nullptr;  // its scene_path and scene.params
  std::uint64_t seed = 0;
  int trials = 0;                    // the manifest's and summary's "trials"
  std::string cycles_per_condition;  // for report.md
  std::string integration;           // each distinct integration setting, for report.md
  std::vector<std::string> inputs;   // besides the experiment file, in order
  nlohmann::json experiments;        // a paper run's parts for the manifest; null: none
};

// The "integrator at accuracy A, contact model M" of a scene's parameters.
std::string IntegrationText(const scene::Parameters& p);

// Writes `sections` with the header's manifest, summary.json and report.md
// into `out`, and commits it (what WriteRunOutput does for an experiment run;
// a kind that is not a design of cycles, calibrate, calls it directly).
RunOutput WriteSections(const RunHeader& header, const std::vector<Section>& sections,
                        OutputDirectory& out, const RunInfo& info);

}  // namespace vahf::report
