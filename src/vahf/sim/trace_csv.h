// Writes a trial's trace as CSV, one row per decision instant. Numbers are
// printed with 17 significant digits (round-trip exact), so the same result
// gives the same bytes.
#pragma once

#include <string>

#include "vahf/sim/trial_result.h"

namespace vahf::sim {

std::string TraceCsv(const TrialResult& result);

}  // namespace vahf::sim
