// Writes a trial's trace as CSV, one row per decision instant. Numbers are
// printed with 17 significant digits (round-trip exact), so the same result
// gives the same bytes.
#pragma once

#include <string>

#include "vahf/sim/trial_result.h"

namespace vahf::sim {

std::string TraceCsv(const TrialResult& result);

// Writes `text` to `path` whole or not at all (a temporary file renamed into
// place). An unwritable path is an InputError naming it.
void WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace vahf::sim
