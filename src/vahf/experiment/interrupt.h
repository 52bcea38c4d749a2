// Ctrl-C for long runs: SIGINT or SIGTERM sets a flag that the Monte Carlo
// runner polls between trials, so trials already running finish and nothing
// half-done is written (docs/outputs.md, "Progress and Ctrl-C").
#pragma once

#include <stdexcept>
#include <string>

namespace vahf::experiment {

// Thrown by the runner when a stop was requested before every trial started. A
// request the user made, not an error of any tier (core/error.h): the command
// writes no output and exits kExitInterrupted.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Installs handlers for SIGINT and SIGTERM that only set the stop flag (an
// async-signal-safe store to a lock-free atomic). Each handler is one-shot
// (SA_RESETHAND): a second Ctrl-C terminates the process at once. Idempotent
// until a signal arrives; call it again to re-arm.
void InstallInterruptHandler();

// True once SIGINT or SIGTERM arrived after InstallInterruptHandler(), or a
// test requested a stop.
bool StopRequested();

// For a host that watches for signals itself (the Python module, which
// installs no handler): set the stop flag as a signal would, and clear it
// before the next call.
void RequestStop();
void ClearStop();

// Test hooks: set and clear the stop flag as a signal would.
void RequestStopForTesting();
void ClearStopForTesting();

}  // namespace vahf::experiment
