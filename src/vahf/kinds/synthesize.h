// `vahf synthesize GENERATOR --out DIR` (and the Python module's
// vahf.synthesize): the model at stated parameter values plays a lab
// (docs/calibration.md), its dataset written into a folder.
#pragma once

#include <string>

#include "vahf/experiment/runner.h"

namespace vahf::kinds {

// Reads the generator file, makes the dataset on options.threads threads
// (the same bits on any count) and writes it into `out` (dataset.json and
// its CSV files); returns the line the command prints: "NAME: N trials of K
// operator(s)[ and S segment row(s)] written to OUT/dataset.json".
std::string Synthesize(const std::string& generator, const std::string& out,
                       experiment::RunnerOptions options);

}  // namespace vahf::kinds
