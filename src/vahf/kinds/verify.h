// `vahf verify RUN_DIR` (docs/reproducibility.md, "Verify a run"): re-runs a
// run from its manifest.json alone and compares what it writes with what the
// run directory holds, so that a reviewer can prove a run is what its
// manifest says.
#pragma once

#include <string>

namespace vahf::kinds {

struct VerifyOptions {
  std::string run_dir;
  int threads = 0;   // worker threads of the re-run; 0: the run's own
  std::string keep;  // where to keep the re-run's output; empty: a temporary
                     // directory, removed at the end
};

// Reads RUN_DIR/manifest.json; checks that every input it lists is present,
// relative to the current directory, with the recorded SHA-256; says how
// this program's build differs from the run's; re-runs the invocation (the
// same experiment, overrides, seed and --trials) and compares the results
// digest and each result file. Prints what it does and finds on stdout;
// returns 0 when every result file is identical, 1 when one differs (the
// first difference named by file, row and column, result_diff.h). An
// unusable manifest or a missing or changed input is an InputError.
int Verify(const VerifyOptions& options);

}  // namespace vahf::kinds
