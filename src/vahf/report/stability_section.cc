#include "vahf/report/stability_section.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

#include "vahf/report/markdown.h"

namespace vahf::report {
namespace {

// The report's short names of the warning kinds, in WarningKind order.
constexpr const char* kShortNames[kWarningKinds] = {
    "nonfinite", "pen", "floor", "retry", "fail", "solver", "rest"};

nlohmann::json WarningCounts(const Warnings& w) {
  nlohmann::json out = nlohmann::json::object();
  for (int k = 0; k < kWarningKinds; ++k) {
    const WarningEntry& e = w.at(static_cast<WarningKind>(k));
    if (e.count > 0) out[WarningName(static_cast<WarningKind>(k))] = e.count;
  }
  return out;
}

// The trials of one case under one integrator, in seed order.
struct Cell {
  const experiment::StabilityCase* c = nullptr;
  std::string integrator;
  std::vector<const experiment::StabilityTrial*> trials;
};

std::vector<Cell> Cells(const experiment::StabilityDesign& d,
                        const std::vector<experiment::StabilityTrial>& trials) {
  std::vector<Cell> out;
  for (const experiment::StabilityTrial& t : trials) {
    const experiment::StabilityCase& c = d.cases[t.case_index];
    const std::string& integrator = c.integrators[t.integrator_index];
    if (out.empty() || out.back().c != &c || out.back().integrator != integrator)
      out.push_back({&c, integrator, {}});
    out.back().trials.push_back(&t);
  }
  return out;
}

// "completed" or, over several seeds, "completed 2, timeout 1".
std::string Statuses(const Cell& cell) {
  std::vector<std::pair<std::string, int>> counts;
  for (const auto* t : cell.trials) {
    const std::string s = sim::StatusName(t->result.status);
    auto it = std::find_if(counts.begin(), counts.end(),
                           [&](const auto& p) { return p.first == s; });
    if (it == counts.end()) {
      counts.emplace_back(s, 1);
    } else {
      ++it->second;
    }
  }
  if (cell.trials.size() == 1) return counts[0].first;
  std::string out;
  for (const auto& [s, n] : counts)
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", s, n);
  return out;
}

std::string Um(double metres) { return fmt::format("{:.3g}", metres * 1e6); }

}  // namespace

std::string CompactWarnings(const Warnings& w) {
  std::string out;
  for (int k = 0; k < kWarningKinds; ++k) {
    const WarningEntry& e = w.at(static_cast<WarningKind>(k));
    if (e.count > 0)
      out += fmt::format("{}{} {}", out.empty() ? "" : ", ", kShortNames[k], e.count);
  }
  return out.empty() ? "-" : out;
}

std::vector<std::string> FailedCases(
    const experiment::StabilityDesign& d,
    const std::vector<experiment::StabilityTrial>& trials) {
  std::vector<bool> failed(d.cases.size(), false);
  for (const experiment::StabilityTrial& t : trials)
    if (!t.failures.empty()) failed[t.case_index] = true;
  std::vector<std::string> out;
  for (std::size_t k = 0; k < d.cases.size(); ++k)
    if (failed[k]) out.push_back(d.cases[k].name);
  return out;
}

namespace {

// A trial's row of stability_trials.csv.
std::vector<Table::Cell> TrialCells(const Cell& cell, const experiment::StabilityTrial& t,
                                    std::int64_t max_steps) {
  const sim::TrialResult& r = t.result;
  return {cell.c->name,
          cell.integrator,
          std::int64_t{t.seed_index},
          std::string(sim::StatusName(r.status)),
          fmt::format("{}", fmt::join(cell.c->expect, " ")),
          std::string(t.failures.empty() ? "yes" : "no"),
          fmt::format("{}", fmt::join(t.failures, "; ")),
          r.end_time,
          r.completion_time,
          r.work,
          r.counters.steps_taken,
          r.counters.steps_attempted,
          max_steps,
          r.counters.realizations,
          CompactWarnings(r.warnings),
          r.warnings.total(),
          r.max_penetration,
          r.penetration_bound,
          r.clearance,
          r.stiffness,
          r.detail};
}

nlohmann::json TrialJson(const experiment::StabilityTrial& t, std::int64_t max_steps) {
  const sim::TrialResult& r = t.result;
  return {{"seed_index", t.seed_index},
          {"status", sim::StatusName(r.status)},
          {"pass", t.failures.empty()},
          {"failures", t.failures},
          {"detail", r.detail},
          {"end_time_s", r.end_time},
          {"steps_taken", r.counters.steps_taken},
          {"steps_attempted", r.counters.steps_attempted},
          {"max_steps", max_steps},
          {"warnings", WarningCounts(r.warnings)},
          {"max_penetration_m", r.max_penetration},
          {"penetration_bound_m", r.penetration_bound}};
}

// Simulated over CPU seconds (0 when no CPU time was measured).
double RealTimeFactor(const sim::TrialResult& r) {
  return r.cpu_seconds > 0 ? r.end_time / r.cpu_seconds : 0.0;
}

nlohmann::json CaseJson(const experiment::StabilityCase& c) {
  return {{"case", c.name},
          {"pointer", c.pointer},
          {"scene", c.scene_path},
          {"position", c.position},
          {"expect", c.expect},
          {"passed", true},
          {"integrators", nlohmann::json::array()}};
}

// The trials table, the measured cost table and their JSON: summary.json's
// cases (each integrator's trials) and measured.json's per trial cost.
struct TrialRecords {
  Table table{{"case",           "integrator",         "seed_index",
               "status",         "expected",           "pass",
               "failures",       "end_time_s",         "completion_time_s",
               "work_j",         "steps_taken",        "steps_attempted",
               "max_steps",      "realizations",       "warnings",
               "warnings_total", "max_penetration_m",  "penetration_bound_m",
               "clearance_m",    "stiffness_pa_per_m", "detail"}};
  Table cost{{"case", "integrator", "seed_index", "simulated_s", "cpu_s", "wall_s",
              "real_time_factor"}};
  nlohmann::json cases = nlohmann::json::array();
  nlohmann::json measured = nlohmann::json::array();
};

TrialRecords RecordTrials(const std::vector<Cell>& cells) {
  TrialRecords out;
  for (const Cell& cell : cells) {
    const experiment::StabilityCase& c = *cell.c;
    if (out.cases.empty() || out.cases.back()["case"] != c.name)
      out.cases.push_back(CaseJson(c));
    nlohmann::json cell_trials = nlohmann::json::array();
    for (const experiment::StabilityTrial* t : cell.trials) {
      const sim::TrialResult& r = t->result;
      const std::int64_t max_steps =
          c.scenes[t->integrator_index].params.simulation.max_steps;
      out.table.AddRow(TrialCells(cell, *t, max_steps));
      out.cost.AddRow({c.name, cell.integrator, std::int64_t{t->seed_index}, r.end_time,
                       r.cpu_seconds, r.wall_seconds, RealTimeFactor(r)});
      cell_trials.push_back(TrialJson(*t, max_steps));
      out.measured.push_back({{"case", c.name},
                              {"integrator", cell.integrator},
                              {"seed_index", t->seed_index},
                              {"cpu_s", r.cpu_seconds},
                              {"wall_s", r.wall_seconds},
                              {"real_time_factor", RealTimeFactor(r)}});
      if (!t->failures.empty()) out.cases.back()["passed"] = false;
    }
    out.cases.back()["integrators"].push_back(
        {{"integrator", cell.integrator}, {"trials", cell_trials}});
  }
  return out;
}

// "pass", or "**FAIL**: " and each distinct failure of the cell's trials.
std::string CellVerdict(const Cell& cell) {
  std::vector<std::string> why;
  for (const auto* t : cell.trials)
    for (const std::string& f : t->failures)
      if (std::find(why.begin(), why.end(), f) == why.end()) why.push_back(f);
  return why.empty() ? "pass" : fmt::format("**FAIL**: {}", fmt::join(why, "; "));
}

// A case under one integrator over its seeds: the warnings summed, the
// deepest contact, bound and step count the largest, CPU and simulated time
// summed.
std::vector<std::string> CellMarkdown(const Cell& cell) {
  Warnings w;
  double depth = 0, bound = 0, cpu = 0, simulated = 0;
  std::int64_t steps = 0;
  for (const auto* t : cell.trials) {
    const sim::TrialResult& r = t->result;
    w.Add(r.warnings);
    depth = std::max(depth, r.max_penetration);
    bound = std::max(bound, r.penetration_bound);
    steps = std::max(steps, r.counters.steps_taken);
    cpu += r.cpu_seconds;
    simulated += r.end_time;
  }
  return {cell.c->name,
          cell.integrator,
          Statuses(cell),
          fmt::format("{}", fmt::join(cell.c->expect, ", ")),
          CellVerdict(cell),
          CompactWarnings(w),
          fmt::format("{} / {}", Um(depth), bound > 0 ? Um(bound) : std::string("-")),
          std::to_string(steps),
          fmt::format("{:.3f}", cpu),
          cpu > 0 ? fmt::format("{:.3g}", simulated / cpu) : std::string("-")};
}

constexpr const char* kLegend =
    "\nWarnings (counts over accepted steps): pen = penetration_bound (contact deeper "
    "than the bound), retry = integrator_retry, floor = step_size_floor, nonfinite = "
    "non_finite_state, fail = integrator_failure, solver = contact_solver; rest = rest "
    "(once a rest: the part in contact and slower than simulation/rest_speed between "
    "decisions for simulation/rest_time or longer). Steps: "
    "accepted steps (the largest "
    "over seeds). CPU and the real-time factor (simulated over CPU seconds, the trial's "
    "thread) are measured on this machine, outside the results digest "
    "(stability_cost.csv, measured.json); over several seeds CPU is their sum.\n\n"
    "Why each trial ended:\n\n";

std::string StabilityMarkdown(const experiment::StabilityDesign& d,
                              const std::vector<experiment::StabilityTrial>& trials,
                              const std::vector<std::string>& failed) {
  std::string md = fmt::format(
      "## Stability: stiff and extreme cases across integrators\n\n"
      "{} case(s), {} trial(s). A trial passes when its status is one of the classes its "
      "case expects, every number of its result (end time, work, deepest contact, final "
      "pose, velocities, forces, factors) is finite, and its accepted steps stay within "
      "simulation/max_steps. **{}**\n\n",
      d.cases.size(), trials.size(),
      failed.empty()
          ? std::string("Every case passes.")
          : fmt::format("{} case(s) fail: {}.", failed.size(), fmt::join(failed, ", ")));
  MarkdownTable table{{"case", "integrator", "status", "expected", "verdict", "warnings",
                       "deepest contact / bound (um)", "steps", "CPU (s)",
                       "real-time factor"}};
  for (const Cell& cell : Cells(d, trials)) table.AddRow(CellMarkdown(cell));
  md += ToMarkdown(table) + kLegend;
  for (const experiment::StabilityTrial& t : trials) {
    const experiment::StabilityCase& c = d.cases[t.case_index];
    md +=
        fmt::format("- {}, {}{}: {} ({})\n", c.name, c.integrators[t.integrator_index],
                    c.seeds > 1 ? fmt::format(", seed {}", t.seed_index) : std::string(),
                    sim::StatusName(t.result.status), t.result.detail);
  }
  return md;
}

}  // namespace

Section StabilitySection(const scene::ExperimentFile& file,
                         const std::vector<experiment::StabilityTrial>& trials) {
  const experiment::StabilityDesign& d = file.Input<experiment::StabilityDesign>();
  TrialRecords records = RecordTrials(Cells(d, trials));
  const std::vector<std::string> failed = FailedCases(d, trials);
  Section s;
  s.tables.emplace_back("stability_trials.csv", std::move(records.table));
  s.measured_tables.emplace_back("stability_cost.csv", std::move(records.cost));
  s.summary = {{"claims", nlohmann::json::array()},
               {"cases", records.cases},
               {"failed_cases", failed},
               {"passed", failed.empty()}};
  s.measured = {{"trials", records.measured}};
  s.markdown = StabilityMarkdown(d, trials, failed);
  return s;
}

}  // namespace vahf::report
