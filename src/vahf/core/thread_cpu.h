// The CPU time of the calling thread, for cost figures (a trial's CPU seconds,
// the benchmarks'): unlike wall time it does not count the time a thread
// waits for a core, so it measures a trial's cost on a busy machine too.
// Measured, never part of a result or a digest.
#pragma once

#include <ctime>

namespace vahf {

// Seconds of CPU this thread has used (POSIX CLOCK_THREAD_CPUTIME_ID).
inline double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace vahf
