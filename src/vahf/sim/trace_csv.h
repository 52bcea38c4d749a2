// Writes a trial's trace as CSV: one row per decision instant ("decision"
// in the first column) and, with TrialOptions::sample_interval, one per
// sample instant ("sample": pose, velocities, forces and penetration; the
// factors are those of decisions only and are 0 there), in time order. Numbers are
// printed with 17 significant digits (round-trip exact), so the same result
// gives the same bytes.
#pragma once

#include <string>

#include "vahf/sim/trial_result.h"

namespace vahf::sim {

std::string TraceCsv(const TrialResult& result);

}  // namespace vahf::sim
