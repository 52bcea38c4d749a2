// The numerical health of an experiment's trials (docs/design.md decision
// 12): per condition, the cycles that ended in a numerical failure (a failure
// of the computation, left out of success rates), the summed warnings record
// of every part trial, and the deepest contact against the penetration bound.
// Every kind's section carries it in summary.json ("health") and report.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "vahf/experiment/design.h"

namespace vahf::report {

// {"conditions": [{"condition", "cycles", "numerical_failures",
//  "max_penetration_m", "penetration_bound_m", "warnings": {kind: {"count",
//  "first_time_s", "detail"}}}], "warnings": total count}
nlohmann::json HealthJson(const experiment::DesignRun& run);

// A "Numerical health" table, one row per condition.
std::string HealthMarkdown(const experiment::DesignRun& run);

}  // namespace vahf::report
