#include "vahf/report/compare_section.h"

#include <fmt/format.h>

#include <cmath>

#include "vahf/report/cost.h"
#include "vahf/report/health.h"

namespace vahf::report {
namespace {

std::string N(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : "-"; }

}  // namespace

Section ComparisonSection(const scene::ExperimentFile& file, const data::LabDataset& lab,
                          const compare::ComparisonResult& r) {
  Section out;
  out.kind = "compare";
  Table t({"quantity", "unit", "margin", "lab_n", "lab_value", "lab_ci_lower", "lab_ci_upper",
           "virtual_n", "virtual_value", "virtual_ci_lower", "virtual_ci_upper", "difference",
           "ci95_lower", "ci95_upper", "ci90_lower", "ci90_upper", "tost_p", "verdict",
           "area_metric", "ks_distance", "ks_p", "reason"});
  nlohmann::json quantities = nlohmann::json::array();
  std::string md = fmt::format(
      "## Virtual against the lab: {}\n\n{}\n\nLab dataset `{}`: {} (provenance: {}). "
      "The virtual design runs {} cycles per lab operator, each operator on its own "
      "streams. \"agree\" means the equivalence test (TOST, 5 %) shows the difference "
      "within the stated margin; \"not shown to agree\" does not mean shown to differ.\n\n"
      "| quantity | margin | lab (95 %) | virtual (95 %) | difference (95 %) | area metric | "
      "KS D (p) | verdict |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n",
      lab.name, file.description, file.comparison.lab_path, lab.description,
      lab.provenance.value("source", ""), file.trials);
  std::string data;
  int index = 0;
  for (const compare::QuantityComparison& q : r.quantities) {
    const bool time = q.target.spec.quantity == "assembly_time";
    const double lab_value = q.target.lab.value, virt_value = q.virtual_stat.value;
    const int lab_n = time ? static_cast<int>(q.lab.times.size()) : q.lab.attempts;
    const int virt_n = time ? static_cast<int>(q.virt.times.size()) : q.virt.attempts;
    const std::string verdict = !q.testable ? "untestable" : q.agree ? "agree" : "not shown to agree";
    const double nan = std::nan("");
    t.AddRow({q.target.label, q.target.unit, q.margin, std::int64_t{lab_n}, lab_value,
              q.lab_ci.lower, q.lab_ci.upper, std::int64_t{virt_n}, virt_value,
              q.virtual_ci.lower, q.virtual_ci.upper, q.testable ? q.difference : nan,
              q.testable ? q.ci95.lower : nan, q.testable ? q.ci95.upper : nan,
              q.testable ? q.ci90.lower : nan, q.testable ? q.ci90.upper : nan,
              q.testable ? q.tost_p : nan, verdict, q.testable ? q.area_metric : nan,
              q.ks ? q.ks->distance : nan, q.ks ? q.ks->p_value : nan, q.verdict});
    quantities.push_back({{"quantity", q.target.label},
                          {"unit", q.target.unit},
                          {"verdict", verdict},
                          {"reason", q.verdict},
                          {"difference", q.testable ? q.difference : nan},
                          {"tost_p", q.testable ? q.tost_p : nan}});
    md += fmt::format("| {} ({}) | +-{} | {} [{}, {}] (n {}) | {} [{}, {}] (n {}) | {} [{}, {}] | "
                      "{} | {} | {} |\n",
                      q.target.label, q.target.unit, N(q.margin), N(lab_value), N(q.lab_ci.lower),
                      N(q.lab_ci.upper), lab_n, N(virt_value), N(q.virtual_ci.lower),
                      N(q.virtual_ci.upper), virt_n, q.testable ? N(q.difference) : "-",
                      q.testable ? N(q.ci95.lower) : "-", q.testable ? N(q.ci95.upper) : "-",
                      q.testable ? N(q.area_metric) : "-",
                      q.ks ? fmt::format("{:.3f} ({:.3g})", q.ks->distance, q.ks->p_value) : "-",
                      q.verdict);
    // x, label, lab, its interval, virtual, its interval
    data += fmt::format("{} \"{}\" {} {} {} {} {} {}\n", index++, q.target.label, lab_value,
                        q.lab_ci.lower, q.lab_ci.upper, virt_value, q.virtual_ci.lower,
                        q.virtual_ci.upper);
  }
  md += "\n";
  out.tables.emplace_back("compare_quantities.csv", std::move(t));
  out.tables.emplace_back("compare_cycles.csv", CyclesTable(r.run));
  out.summary = {{"quantities", quantities}, {"claims", nlohmann::json::array()},
                 {"health", HealthJson(r.run)}};
  out.markdown = md + HealthMarkdown(r.run);
  Table cost = CostTable(r.run);
  out.markdown += CostMarkdown(cost);
  out.measured = {{"cost", CostJson(cost)}};
  out.measured_tables.emplace_back("compare_cost.csv", std::move(cost));
  out.plots.push_back(
      {"plots/compare_quantities.png",
       "Lab and virtual, quantity by quantity (mean or rate, 95 % interval)",
       "$d << EOD\n" + data +
           "EOD\nset title 'Virtual against the lab'\n"
           "set ylabel 'value (s for times, 1 for rates)'\n"
           "set xrange [-0.5:" + std::to_string(r.quantities.size()) + "-0.5]\n"
           "set xtics rotate by -30\nset grid y\nset key outside bottom center horizontal\n"
           "plot $d using ($1-0.12):3:4:5:xtic(2) with yerrorbars pt 7 title 'lab', "
           "'' using ($1+0.12):6:7:8 with yerrorbars pt 5 title 'virtual'\n"});
  return out;
}

}  // namespace vahf::report
