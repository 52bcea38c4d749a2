// `vahf replay RUN_DIR --cycle TABLE:ROW` (docs/reproducibility.md,
// "Replay"): runs one cycle of a run again, alone, from its manifest and the
// row of its cycles table (condition, group, stream index, initial work,
// repetition), and shows that it reproduces the cycle's rows bit for bit; a
// failed or slow cycle of a long run can then be traced in isolation.
#pragma once

#include <string>

namespace vahf::kinds {

struct ReplayOptions {
  std::string run_dir;
  std::string cycle;  // TABLE:ROW, ROW the 1-based data row (the header is row 0)
  std::string trace;  // write the cycle's trace here (CSV; empty: none)
  double sample = 0;  // with `trace`: also a row every DT s of simulated time
  // How errors name sample and trace: the command's options, or the Python
  // module's arguments.
  const char* sample_option = "--sample";
  const char* trace_needed = "needs --trace FILE to write the rows to";
};

// Reads and checks the run (recorded_run.h), finds the row's experiment (a
// paper run's part by the table's name) and condition, runs the cycle with
// its recorded stream, work and repetition, prints its rows and compares
// them with the table's rows of that cycle. Returns 0 when they are
// identical, 1 when one differs (the first difference named, result_diff.h).
// A sample that is not > 0 or comes without a trace, a bad --cycle, a
// table that is no cycles table of the run, a row past its end, a kind
// whose cycles cannot be replayed, and the input errors of ReadRecordedRun
// are InputErrors.
int Replay(const ReplayOptions& options);

}  // namespace vahf::kinds
