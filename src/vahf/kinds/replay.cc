#include "vahf/kinds/replay.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include "vahf/core/atomic_file.h"
#include "vahf/core/error.h"
#include "vahf/data/csv.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/recorded_run.h"
#include "vahf/report/result_diff.h"
#include "vahf/report/section.h"
#include "vahf/sim/trace_csv.h"

namespace vahf::kinds {
namespace {

namespace fs = std::filesystem;

const char* const kCycleRule =
    "takes TABLE:ROW, a cycles table of the run and one of its data rows (1 is the "
    "first after the header), e.g. assembly_time_cycles.csv:1";

// The row of the cycles table that --cycle names, and the table parsed.
struct CycleRow {
  std::string table;
  data::CsvFile csv;
  std::size_t row = 0;  // 0-based into csv.rows
};

CycleRow FindRow(const report::RecordedRun& run, const std::string& run_dir,
                 const std::string& spec) {
  const std::size_t colon = spec.rfind(':');
  CycleRow out;
  std::size_t row = 0;
  const char* end = spec.data() + spec.size();
  if (colon == std::string::npos ||
      std::from_chars(spec.data() + colon + 1, end, row).ptr != end || row == 0)
    throw InputError("--cycle", "", spec, kCycleRule);
  out.table = spec.substr(0, colon);
  const auto& files = run.result_files;
  if (std::find(files.begin(), files.end(), out.table) == files.end() ||
      out.table.size() < 10 || out.table.compare(out.table.size() - 10, 10, "cycles.csv"))
    throw InputError("--cycle", "", spec,
                     fmt::format("names no cycles table of the run ({} lists its result "
                                 "files; a cycles table's name ends in cycles.csv)",
                                 run.file));
  const std::string path = (fs::path(run_dir) / out.table).string();
  const std::optional<std::string> bytes = ReadResultFile(run_dir, out.table);
  if (!bytes) throw InputError(path, "", "", "cannot open the file for reading");
  out.csv = data::ParseCsv(*bytes, path);
  if (row > out.csv.rows.size())
    throw InputError("--cycle", "", spec,
                     fmt::format("{} has {} data rows", out.table, out.csv.rows.size()));
  out.row = row - 1;
  return out;
}

// The experiment whose kind wrote `table` (KIND_...): the file itself or a
// part of a run of experiments.
const scene::ExperimentFile& Owner(const scene::ExperimentFile& file,
                                   const std::string& table, const std::string& spec) {
  const Kind& kind = FindKind(file.kind);
  std::vector<const scene::ExperimentFile*> candidates = {&file};
  if (kind.parts) candidates = kind.parts(file);
  for (const scene::ExperimentFile* c : candidates) {
    const std::string prefix = c->kind + "_";
    if (table.compare(0, prefix.size(), prefix) != 0) continue;
    if (!FindKind(c->kind).conditions)
      throw InputError("--cycle", "", spec,
                       "the cycles of a " + c->kind + " run cannot be replayed yet");
    return *c;
  }
  throw InputError("--cycle", "", spec,
                   "names a table no experiment of the run wrote as its cycles table");
}

// The lines of `csv`'s rows of the cycle that `r` is a row of, with the
// header first, and their 0-based row indices.
std::string CycleLines(const data::CsvFile& csv, const data::CsvRow& r,
                       std::vector<std::size_t>* rows) {
  std::vector<std::size_t> key;  // the columns that name a cycle
  for (const char* column : {"condition", "group", "cycle"})
    key.push_back(static_cast<std::size_t>(
        std::find(csv.header.begin(), csv.header.end(), column) - csv.header.begin()));
  std::string out = data::CsvLine(csv.header);
  for (std::size_t k = 0; k < csv.rows.size(); ++k) {
    const auto& f = csv.rows[k].fields;
    if (std::all_of(key.begin(), key.end(),
                    [&](std::size_t c) { return f[c] == r.fields[c]; })) {
      out += data::CsvLine(f);
      rows->push_back(k);
    }
  }
  return out;
}

// Every part's trace, one after another, a `part` column first.
std::string CycleTrace(const experiment::CycleResult& cycle) {
  std::string out;
  for (const experiment::PartRun& p : cycle.parts) {
    std::istringstream lines(sim::TraceCsv(p.trial));
    std::string line;
    for (bool header = true; std::getline(lines, line); header = false) {
      if (header && !out.empty()) continue;
      out += (header ? std::string("part") : data::CsvField(p.trial.part)) + "," + line +
             "\n";
    }
  }
  return out;
}

}  // namespace

int Replay(const ReplayOptions& options) {
  if (options.sample != 0 && !(options.sample > 0))
    throw InputError(options.sample_option, "", fmt::format("{}", options.sample),
                     "must be > 0 s");
  if (options.sample > 0 && options.trace.empty())
    throw InputError(options.sample_option, "", fmt::format("{}", options.sample),
                     options.trace_needed);
  const report::RecordedRun run = ReadRecordedRun(options.run_dir);
  const CycleRow found = FindRow(run, options.run_dir, options.cycle);
  const data::CsvTable table(
      found.csv,
      {"condition", "group", "cycle", "start_minute", "initial_work_J", "repetition"},
      {"position", "part", "status", "part_start_s", "part_time_s", "work_end_J",
       "cycle_completed", "cycle_time_s"});
  const data::CsvRow& row = table.rows()[found.row];
  const std::string name = table.Cell(row, "condition").text();
  const std::string group = table.Cell(row, "group").text();
  experiment::CycleRecord record;
  record.cycle = static_cast<std::uint64_t>(
      table.Cell(row, "cycle").Integer(0, std::numeric_limits<std::int64_t>::max()));
  record.start_minute = table.Cell(row, "start_minute").Number();
  record.initial_work = table.Cell(row, "initial_work_J").Number();
  record.repetition = static_cast<int>(table.Cell(row, "repetition").Integer(1, 1 << 30));

  const scene::ExperimentFile file = LoadRecordedExperiment(run);
  const experiment::RunSettings settings = RecordedSettings(run, 1);
  const scene::ExperimentFile& owner = Owner(file, found.table, options.cycle);
  std::vector<experiment::Condition> conditions =
      FindKind(owner.kind).conditions(owner, settings);
  const auto it = std::find_if(conditions.begin(), conditions.end(), [&](const auto& c) {
    return c.name == name && c.group == group;
  });
  if (it == conditions.end())
    table.Cell(row, "condition")
        .Fail(fmt::format("names no condition of group '{}' of {}", group, owner.file));
  const double time_limit = it->scene->params.simulation.time_limit;
  if (options.sample > 0 &&
      (options.sample > time_limit || time_limit / options.sample > 1e6))
    throw InputError("--sample", "", fmt::format("{}", options.sample),
                     fmt::format("must be at most the scene's time_limit ({} s) and give "
                                 "at most 1e6 rows a part: DT >= {} s",
                                 time_limit, time_limit / 1e6));
  std::printf("%s\n",
              fmt::format("replay {} row {}: {}, condition '{}'{}, cycle {}, seed {}, "
                          "initial work {} J, repetition {}",
                          found.table, found.row + 1, owner.file, name,
                          group.empty() ? "" : " (" + group + ")", record.cycle,
                          run.invocation.seed, table.Cell(row, "initial_work_J").text(),
                          record.repetition)
                  .c_str());
  record.result = experiment::RunCycle(
      sim::BuildSequenceModels(*it->scene), run.invocation.seed, record.cycle,
      record.initial_work, true, record.repetition, options.sample);
  if (!options.trace.empty()) {
    WriteFileAtomically(options.trace, CycleTrace(record.result));
    std::printf("trace: %s\n", options.trace.c_str());
  }
  experiment::DesignRun replayed;
  replayed.conditions = {*it};
  replayed.records = {std::move(record)};
  const std::string again = report::CyclesTable(replayed).ToCsv();
  std::fputs(again.c_str(), stdout);
  std::vector<std::size_t> rows;
  const std::string recorded = CycleLines(found.csv, row, &rows);
  const auto d = report::FirstDifference(found.table, recorded, again);
  if (!d) {
    std::printf("replay: identical: the cycle's %zu rows of %s\n", rows.size(),
                found.table.c_str());
    return 0;
  }
  report::ResultDifference shown = *d;
  if (shown.row > 0 && static_cast<std::size_t>(shown.row) <= rows.size()) {
    const data::CsvRow& r = found.csv.rows[rows[static_cast<std::size_t>(shown.row) - 1]];
    shown.row = static_cast<int>(rows[static_cast<std::size_t>(shown.row) - 1]) + 1;
    shown.line = r.line;
  }
  std::printf("replay: different: %s\n", shown.Text().c_str());
  return 1;
}

}  // namespace vahf::kinds
