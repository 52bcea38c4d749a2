// What one experiment contributes to a run's output (docs/outputs.md): tidy
// tables, its part of summary.json (statistics and the paper's claims, each
// with its verdict: yes, no or untestable), a Markdown section of report.md and its
// plots. The analysis of each kind lives in its own file; this header declares them.
// A section describes its CSV tables as Table (table.h), its report.md tables as
// MarkdownTable (markdown.h) and its plots as Figure (figure.h); each has one writer.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vahf/experiment/design.h"
#include "vahf/report/table.h"
#include "vahf/stats/paired.h"
#include "vahf/stats/summary.h"
#include "vahf/stats/welch.h"

namespace vahf::report {

struct Plot {
  std::string file;    // relative to the run directory: "plots/NAME.png"
  std::string title;   // the caption in report.md
  std::string script;  // gnuplot, with inline data: GnuplotScript (figure.h)
};

struct Section {
  std::string kind;
  std::vector<std::pair<std::string, Table>> tables;  // file name -> table
  // Other result files (digested like the tables): file name -> bytes.
  std::vector<std::pair<std::string, std::string>> files;
  nlohmann::json summary;  // always holds "claims": a list (possibly empty)
  std::string markdown;
  std::vector<Plot> plots;
  // What this machine measured (wall times) and what follows from it: written
  // beside the results but outside the results digest (docs/outputs.md,
  // "Measured files"), as tables and as this section's part of measured.json
  // (null: none).
  std::vector<std::pair<std::string, Table>> measured_tables;
  nlohmann::json measured;
};

// A claim of the paper tested on the run, with its verdict: "yes" when the
// statistical test named in `test` supports it at the 5 % level, else "no";
// `evidence` gives the test's figures (and, for "no", what the model gave
// instead). JSON: claim, verdict, reproduced (verdict == "yes"), test,
// evidence.
nlohmann::json Claim(const std::string& claim, bool reproduced, const std::string& test,
                     const std::string& evidence);
// A claim the run cannot test (too few completions, no spread, a condition
// missing): verdict "untestable", `why` in a sentence. It stays in the table.
nlohmann::json UntestableClaim(const std::string& claim, const std::string& test,
                               const std::string& why);

// Welch's t test of a against b (stats/welch.h) when it is defined: each has
// at least two values and not both lack spread; otherwise nothing, and `why`
// says which (naming the samples `a_name` and `b_name`).
std::optional<stats::WelchResult> WelchIfDefined(const std::vector<double>& a,
                                                 const std::vector<double>& b,
                                                 const std::string& a_name,
                                                 const std::string& b_name,
                                                 std::string* why);

// Student's paired t test of a against b, pair by pair (stats/paired.h): the
// outcomes of one cycle under two conditions on the same streams. Defined
// when there are two pairs and the differences vary; otherwise nothing, and
// `why` says which (`pairs` names the pairs: "cycles completed in both").
std::optional<stats::PairedTResult> PairedIfDefined(const std::vector<double>& a,
                                                    const std::vector<double>& b,
                                                    const std::string& pairs,
                                                    std::string* why);

// "mean [lower, upper]" of a summary for report.md, 3 decimals; the mean
// alone without an interval (one sample), "-" without a mean.
std::string MeanCi(const stats::Summary& s);

// One row per part trial of every cycle: condition, group, cycle, part,
// status, start and completion times, work. Every paper kind writes it.
Table CyclesTable(const experiment::DesignRun& run);

Section Table1Section(const experiment::ExperimentRun& run);
Section AssemblyTimeSection(const experiment::ExperimentRun& run);
Section HumanFactorsGroupsSection(const experiment::ExperimentRun& run);
Section FatigueSection(const experiment::ExperimentRun& run);
// Error against run time of each setting (report/precision.h).
Section PrecisionSection(const experiment::ExperimentRun& run);

// The section of a design of cycles of kind `kind` (the registry's name, which
// keys the section in summary.json): its kind's analysis (one of the above,
// as the kind registry, kinds/kind.h, pairs them) with the run's numerical
// health (health.h) in summary["health"] and at the end of its markdown, and,
// but for a kind that measures its cost itself (precision, per setting: its
// `measured` is set), what its trials cost (cost.h) as a measured table
// KIND_cost.csv, measured.json and markdown.
Section SectionFor(const std::string& kind, const experiment::ExperimentRun& run,
                   Section analysis);

}  // namespace vahf::report
