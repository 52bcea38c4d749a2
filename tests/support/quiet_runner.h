// Runner options for tests that run designs: two threads (so thread
// independence is exercised), no progress lines.
#pragma once

#include "vahf/experiment/runner.h"

namespace vahf::testing {

inline experiment::RunnerOptions QuietRunner() {
  experiment::RunnerOptions o;
  o.threads = 2;
  o.progress = false;
  return o;
}

}  // namespace vahf::testing
