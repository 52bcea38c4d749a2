// A recorded run as `vahf verify` and `vahf replay` take it up again
// (docs/reproducibility.md): its manifest read, its inputs checked, its
// experiment loaded as the run loaded it.
#pragma once

#include <optional>
#include <string>

#include "vahf/experiment/design.h"
#include "vahf/report/manifest.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::kinds {

// RUN_DIR/manifest.json, read (report::ReadManifest), with every input it
// lists present at its recorded path, relative to the current directory,
// with its recorded SHA-256. An InputError names the manifest, the pointer
// and the rule otherwise (a missing or changed input), or RUN_DIR when it is
// not a directory.
report::RecordedRun ReadRecordedRun(const std::string& run_dir);

// The experiment the run read, with the override file it was given.
scene::ExperimentFile LoadRecordedExperiment(const report::RecordedRun& run);

// The bytes of result file `name` of the run in `run_dir`; nothing when it
// is not a readable regular file.
std::optional<std::string> ReadResultFile(const std::string& run_dir,
                                          const std::string& name);

// The run's settings: its seed and --trials, on `threads` threads.
experiment::RunSettings RecordedSettings(const report::RecordedRun& run, int threads);

}  // namespace vahf::kinds
