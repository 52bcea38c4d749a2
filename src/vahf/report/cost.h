// What an experiment's trials cost on this machine (the measure of the
// README's Performance section, in every run): per part, the CPU seconds of a trial
// (median, 99th percentile, largest), the simulated seconds and the real-time factor
// (simulated over CPU seconds). CPU time is the trial's thread's (core/thread_cpu.h), so
// the figures hold whatever the thread count. Measured: the table is a measured file,
// outside the results digest (docs/outputs.md, "Measured files").
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "vahf/experiment/design.h"
#include "vahf/report/table.h"

namespace vahf::report {

// One row per part, in the order the parts first appear: part, trials,
// cpu_p50_s, cpu_p99_s, cpu_max_s, cpu_total_s, simulated_mean_s, rtf_p50.
Table CostTable(const experiment::DesignRun& run);

// The same as {"parts": [{column: value}]}, for measured.json.
nlohmann::json CostJson(const Table& cost);

// A "Cost per trial" subsection of report.md.
std::string CostMarkdown(const Table& cost);

}  // namespace vahf::report
