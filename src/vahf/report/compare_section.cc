#include "vahf/report/compare_section.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "vahf/report/cost.h"
#include "vahf/report/figure.h"
#include "vahf/report/health.h"
#include "vahf/report/markdown.h"

namespace vahf::report {
namespace {

std::string N(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : "-"; }

bool Finite(const stats::Interval& i) {
  return std::isfinite(i.lower) && std::isfinite(i.upper);
}

// "9.2 [8.1, 10.3] (n 12)"; a point without an interval says so; n 0 is a
// count the lab did not state.
std::string Side(double value, const stats::Interval& ci, int n) {
  if (!std::isfinite(value)) return "-";
  return N(value) +
         (Finite(ci) ? fmt::format(" [{}, {}]", N(ci.lower), N(ci.upper))
                     : " (no interval)") +
         (n > 0 ? fmt::format(" (n {})", n) : " (n not stated)");
}

// The samples behind a side's value: successful trials for a time, attempts
// for a rate, values at the instant for eta and lambda_c (attempts too); for
// a reported statistic the n the lab states (0: none).
int SideN(const compare::QuantityComparison& q, bool lab) {
  const bool time = q.target.spec.quantity == "assembly_time";
  if (lab && q.reported) return q.target.lab.n;
  const calibrate::TargetSamples& s = lab ? q.lab : q.virt;
  return time ? static_cast<int>(s.times.size()) : s.attempts;
}

// The rows that share a table and a plot: times (s), rates, and eta and
// lambda_c at instants (both in 1, but not shares of attempts).
std::string GroupOf(const compare::QuantityComparison& q) {
  if (q.target.unit == "s") return "s";
  return scene::AtInstant(q.target.spec.quantity) ? "factor" : "rate";
}

std::string Verdict(const compare::QuantityComparison& q) {
  return !q.testable ? "untestable" : q.agree ? "agree" : "not shown to agree";
}

// What a group's rows are (GroupOf), on a plot's axis and a table's heading.
struct UnitText {
  const char* heading;  // "Mean assembly times"
  const char* axis;     // "mean assembly time (s)"
  const char* plot;     // "plots/compare_times.png"
  const char* unit;     // of its values: "s" or "1"
  const char* column;   // in its table's headings: "s", "rate", "1"
};
UnitText TextOf(const std::string& group) {
  if (group == "s")
    return {"Mean assembly times (s)", "mean assembly time (s)",
            "plots/compare_times.png", "s", "s"};
  if (group == "factor")
    return {"Human factors at an instant: eta (Eq. 2) and lambda_c (Eq. 3)",
            "mean eta or lambda_c (1)", "plots/compare_factors.png", "1", "1"};
  return {"Success rates (1: a share of attempts)", "success rate (1)",
          "plots/compare_rates.png", "1", "rate"};
}

// A gnuplot double-quoted string; with `lines`, each ", " starts a new line.
std::string Quoted(const std::string& s, bool lines = false) {
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (lines && s.compare(i, 2, ", ") == 0) {
      out += "\\n";
      ++i;
      continue;
    }
    if (s[i] == '"' || s[i] == '\\') out += '\\';
    out += s[i];
  }
  return out + "\"";
}

// Columns of one side of a plot row: value, its interval, 1 when it has one
// (0: a point, set in *point; -1: no value).
DataRow& AddSide(DataRow& row, double v, const stats::Interval& ci, bool* point) {
  if (!std::isfinite(v)) return row.Integer(0).Integer(0).Integer(0).Integer(-1);
  if (!Finite(ci)) {
    *point = true;
    return row.Number(v).Number(v).Number(v).Integer(0);
  }
  return row.Number(v).Number(ci.lower).Number(ci.upper).Integer(1);
}

// The tic of a row: its label without the quantity the plot names, a line
// each ("all / segment 4 / real", "block / male P5").
std::string Tic(const compare::QuantityComparison& q) {
  const std::string prefix = q.target.spec.quantity + " of ";
  std::string tic = q.target.label;
  if (tic.rfind(prefix, 0) == 0) tic.erase(0, prefix.size());
  if (const std::size_t op = tic.find(", operator "); op != std::string::npos)
    tic.erase(op + 2, 9);  // "operator "
  return Quoted(tic, true);
}

// Lab beside virtual for the rows of one group, each with its 95 % interval;
// a value without an interval as a point of its own style.
Plot UnitPlot(const std::vector<const compare::QuantityComparison*>& rows,
              const std::string& group) {
  const UnitText text = TextOf(group);
  std::vector<DataRow> data;
  std::string tics;
  bool lab_point = false, virt_point = false;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const compare::QuantityComparison& q = *rows[i];
    DataRow row = DataRow().Integer(static_cast<std::int64_t>(i));
    AddSide(row, q.target.lab.value, q.lab_ci, &lab_point);
    AddSide(row, q.virtual_stat.value, q.virtual_ci, &virt_point);
    data.push_back(row);
    tics += fmt::format("{}{} {}", i ? ", " : "", Tic(q), i);
  }
  Figure f;
  f.Data("d", data)
      .Set("title " + Quoted(std::string("Virtual against the lab: ") + text.heading))
      .Set("ylabel " + Quoted(text.axis));
  if (group == "s")
    f.Set("yrange [0:*]").Set("offsets 0, 0, graph 0.08, 0");
  else
    f.Set("yrange [0:1.05]");
  f.CategoryRange(rows.size())
      .Set("xtics (" + tics + ")")
      .Set("grid y")
      .Set("key outside top center horizontal")
      .Set("bmargin 5")
      .Draw({"$d", "($1-0.12):($5==1?$2:1/0):3:4", "with yerrorbars pt 7 lc 1",
             "lab (95 %)"})
      .Draw({"''", "($1+0.12):($9==1?$6:1/0):7:8", "with yerrorbars pt 5 lc 2",
             "virtual (95 %)"});
  if (lab_point)
    f.Draw({"''", "($1-0.12):($5==0?$2:1/0)", "with points pt 6 ps 1.5 lc 1",
            "lab, no interval"});
  if (virt_point)
    f.Draw({"''", "($1+0.12):($9==0?$6:1/0)", "with points pt 4 ps 1.5 lc 2",
            "virtual, no interval"});
  return {text.plot,
          std::string(text.heading) + ": lab and virtual side by side (95 % intervals)",
          GnuplotScript(f)};
}

// Every cycle the comparison ran as one design, for the cycles table, health
// and cost: the lab's operators, the fatigue pilot and its segments.
experiment::DesignRun AllCycles(const compare::ComparisonResult& r) {
  experiment::DesignRun out;
  for (const experiment::DesignRun* d : {&r.run, &r.fatigue.pilot, &r.fatigue.run}) {
    const std::size_t offset = out.conditions.size();
    out.conditions.insert(out.conditions.end(), d->conditions.begin(),
                          d->conditions.end());
    for (experiment::CycleRecord c : d->records) {
      c.condition += offset;
      out.records.push_back(std::move(c));
    }
  }
  return out;
}

// What the virtual side ran, in a sentence or two.
std::string Designs(const scene::ExperimentFile& file, const compare::ComparisonResult& r,
                    int trials) {
  std::string out;
  if (!r.run.conditions.empty())
    out += fmt::format(
        "For the quantities without a segment the virtual design runs {} cycles per lab "
        "operator ({} condition(s): {}), each operator on its own streams. ",
        trials, r.run.conditions.size(),
        r.run.conditions.size() == 1 ? r.run.conditions[0].name : "the lab's operators");
  if (!r.fatigue.run.conditions.empty()) {
    std::string segments;
    for (int s : r.fatigue.segments)
      segments += fmt::format("{}{}", segments.empty() ? "" : ", ", s + 1);
    out += fmt::format(
        "For the segment quantities the scene's operator works {:g} min in {} segments "
        "(the fatigue design): a pilot of {} cycles from A = 0 measured the work rate, "
        "{:.4g} J per second of assembly, and segment(s) {} ran {} cycles each, every "
        "cycle starting with the work done by its minute. ",
        file.Input<compare::ComparisonDesign>().fatigue.duration_min,
        file.Input<compare::ComparisonDesign>().fatigue.segments,
        r.fatigue.pilot.records.size(), r.fatigue.work_rate, segments, trials);
  }
  return out;
}

// The row of compare_quantities.csv: both sides, the tests and the verdict;
// the tests' figures NaN when the quantity is untestable.
std::vector<Table::Cell> QuantityCells(const compare::QuantityComparison& q) {
  const double nan = std::nan("");
  const auto tested = [&](double x) { return q.testable ? x : nan; };
  return {q.target.label,
          q.target.unit,
          std::int64_t{q.target.spec.segment},
          q.target.spec.condition,
          compare::LabBasis(q.target, q.reported),
          q.margin,
          std::int64_t{SideN(q, true)},
          q.target.lab.value,
          q.lab_ci.lower,
          q.lab_ci.upper,
          std::int64_t{SideN(q, false)},
          q.virtual_stat.value,
          q.virtual_ci.lower,
          q.virtual_ci.upper,
          tested(q.difference),
          tested(q.ci95.lower),
          tested(q.ci95.upper),
          tested(q.ci90.lower),
          tested(q.ci90.upper),
          tested(q.tost_p),
          Verdict(q),
          tested(q.area_metric),
          q.ks ? q.ks->distance : nan,
          q.ks ? q.ks->p_value : nan,
          q.ks_unavailable,
          q.verdict};
}

nlohmann::json QuantityJson(const compare::QuantityComparison& q) {
  const double nan = std::nan("");
  return {{"quantity", q.target.label},
          {"unit", q.target.unit},
          {"lab_basis", compare::LabBasis(q.target, q.reported)},
          {"lab_value", q.target.lab.value},
          {"virtual_value", q.virtual_stat.value},
          {"verdict", Verdict(q)},
          {"reason", q.verdict},
          {"difference", q.testable ? q.difference : nan},
          {"tost_p", q.testable ? q.tost_p : nan}};
}

std::vector<std::string> QuantityMarkdown(const compare::QuantityComparison& q) {
  return {q.target.label,
          compare::LabBasis(q.target, q.reported),
          "+-" + N(q.margin),
          Side(q.target.lab.value, q.lab_ci, SideN(q, true)),
          Side(q.virtual_stat.value, q.virtual_ci, SideN(q, false)),
          q.testable ? fmt::format("{} [{}, {}]", N(q.difference), N(q.ci95.lower),
                                   N(q.ci95.upper))
                     : "-",
          q.testable ? N(q.area_metric) : "-",
          q.ks ? fmt::format("{:.3f} ({:.3g})", q.ks->distance, q.ks->p_value)
               : "n/a: " + q.ks_unavailable,
          q.verdict};
}

// The quantities grouped by GroupOf, the groups in the order they first appear.
std::vector<std::pair<std::string, std::vector<const compare::QuantityComparison*>>>
ByUnit(const std::vector<compare::QuantityComparison>& quantities) {
  std::vector<std::pair<std::string, std::vector<const compare::QuantityComparison*>>>
      units;
  for (const compare::QuantityComparison& q : quantities) {
    auto it = units.begin();
    while (it != units.end() && it->first != GroupOf(q)) ++it;
    if (it == units.end()) it = units.insert(units.end(), {GroupOf(q), {}});
    it->second.push_back(&q);
  }
  return units;
}

// compare_quantities.csv: a row per quantity (QuantityCells).
Table QuantitiesTable() {
  return Table({"quantity",
                "unit",
                "segment",
                "condition",
                "lab_basis",
                "margin",
                "lab_n",
                "lab_value",
                "lab_ci_lower",
                "lab_ci_upper",
                "virtual_n",
                "virtual_value",
                "virtual_ci_lower",
                "virtual_ci_upper",
                "difference",
                "ci95_lower",
                "ci95_upper",
                "ci90_lower",
                "ci90_upper",
                "tost_p",
                "verdict",
                "area_metric",
                "ks_distance",
                "ks_p",
                "ks_note",
                "reason"});
}

std::string CompareIntro(const scene::ExperimentFile& file, const data::LabDataset& lab,
                         const compare::ComparisonResult& r, int trials) {
  return fmt::format(
      "## Virtual against the lab: {}\n\nLab dataset `{}`: {} (provenance: {}). {}"
      "\"agree\" means the equivalence test (TOST, 5 %) shows the difference within the "
      "stated margin; \"not shown to agree\" does not mean shown to differ. Against a "
      "value the lab reports without its trials the test is the normal approximation, "
      "the area metric is the distance to that value, and there is no KS test.\n\n",
      lab.name, file.Input<compare::ComparisonDesign>().lab_path, lab.description,
      lab.provenance.value("source", ""), Designs(file, r, trials));
}

// The Markdown table of one group's quantities (QuantityMarkdown).
MarkdownTable UnitTable(const std::string& group) {
  const std::string unit = TextOf(group).unit, u = TextOf(group).column;
  return MarkdownTable({"quantity", "lab from", fmt::format("margin ({})", unit),
                        fmt::format("lab ({}, 95 %)", u),
                        fmt::format("virtual ({}, 95 %)", u),
                        fmt::format("difference ({}, 95 %)", u),
                        fmt::format("area metric ({})", unit), "KS D (p)", "verdict"});
}

}  // namespace

Section ComparisonSection(const scene::ExperimentFile& file, const data::LabDataset& lab,
                          const compare::ComparisonResult& r, int trials) {
  Section out;
  Table t = QuantitiesTable();
  nlohmann::json quantities = nlohmann::json::array();
  std::string md = CompareIntro(file, lab, r, trials);
  // One table and one plot per group (times, rates, eta and lambda_c).
  for (const auto& [group, rows] : ByUnit(r.quantities)) {
    MarkdownTable table = UnitTable(group);
    for (const compare::QuantityComparison* q : rows) {
      t.AddRow(QuantityCells(*q));
      quantities.push_back(QuantityJson(*q));
      table.AddRow(QuantityMarkdown(*q));
    }
    md += fmt::format("### {}\n\n", TextOf(group).heading) + ToMarkdown(table) + "\n";
    out.plots.push_back(UnitPlot(rows, group));
  }
  const experiment::DesignRun cycles = AllCycles(r);
  out.tables.emplace_back("compare_quantities.csv", std::move(t));
  out.tables.emplace_back("compare_cycles.csv", CyclesTable(cycles));
  out.summary = {{"quantities", quantities},
                 {"claims", nlohmann::json::array()},
                 {"health", HealthJson(cycles)}};
  out.markdown = md + HealthMarkdown(cycles);
  Table cost = CostTable(cycles);
  out.markdown += CostMarkdown(cost);
  out.measured = {{"cost", CostJson(cost)}};
  out.measured_tables.emplace_back("compare_cost.csv", std::move(cost));
  return out;
}

}  // namespace vahf::report
