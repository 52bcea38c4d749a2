// Paper Table 1: the factors at instants a-d of each part, virtual beside the
// paper's, and the claim that eta rises as the part nears its final position.
#include <fmt/format.h>

#include <array>
#include <map>

#include "vahf/experiment/instants.h"
#include "vahf/experiment/table1_reference.h"
#include "vahf/report/section.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

constexpr std::array<char, 4> kInstants = {'a', 'b', 'c', 'd'};
const std::array<const char*, 9> kColumns = {"V",        "f", "eta", "r",  "g",
                                             "lambda_c", "t", "A",   "psi"};

// The nine Table 1 quantities of a row; t and A counted from the cycle's start.
std::array<double, 9> Values(const sim::TraceRow& row, const experiment::PartRun& part) {
  const auto& f = row.factors;
  return {f.V,      f.f,    f.eta, f.r, f.g, f.lambda_c, part.start_time + row.time,
          row.work, row.psi};
}

std::array<double, 9> PaperValues(const experiment::Table1Row& r) {
  return {r.V, r.f, r.eta, r.r, r.g, r.lambda_c, r.t, r.A, r.psi_c};
}

}  // namespace

Section Table1Section(const experiment::ExperimentRun& run) {
  const scene::ExperimentFile& file = *run.file;
  const scene::Scene& scene = file.scene;
  Section out;
  out.kind = "table1";
  out.tables.emplace_back("table1_cycles.csv", CyclesTable(run.run));

  std::optional<experiment::Table1> paper;
  if (!file.paper_table_path.empty())
    paper = experiment::LoadTable1(file.paper_table_path);

  // Every instant of every completed cycle.
  Table instants({"cycle", "position", "part", "instant", "V", "f", "eta", "r", "g",
                  "lambda_c", "t_s", "A_J", "psi"});
  const std::size_t n_parts = scene.sequence.size();
  // [part][instant][column] -> samples; eta at a and d per cycle, for the claim.
  std::vector<std::array<std::array<std::vector<double>, 9>, 4>> samples(n_parts);
  std::vector<std::vector<double>> eta_rise(n_parts);
  int completed = 0;
  for (const experiment::CycleRecord& r : run.run.records) {
    if (!r.result.completed) continue;
    ++completed;
    for (std::size_t p = 0; p < n_parts; ++p) {
      const experiment::PartRun& part = r.result.parts[p];
      const scene::Part& sp = scene.parts[scene.sequence[p]];
      const experiment::Instants in = experiment::FindInstants(
          part.trial, sp.target.Rotation(), scene.params.simulation.completion_angle_deg);
      const std::array<const std::optional<sim::TraceRow>*, 4> rows = {&in.a, &in.b,
                                                                       &in.c, &in.d};
      for (std::size_t k = 0; k < 4; ++k) {
        if (!*rows[k]) continue;
        const auto v = Values(**rows[k], part);
        std::vector<Table::Cell> cells = {static_cast<std::int64_t>(r.cycle),
                                          static_cast<std::int64_t>(p), sp.name,
                                          std::string(1, kInstants[k])};
        for (std::size_t c = 0; c < 9; ++c) {
          cells.emplace_back(std::in_place_type<double>, v[c]);
          samples[p][k][c].push_back(v[c]);
        }
        instants.AddRow(std::move(cells));
      }
      if (in.a && in.d) eta_rise[p].push_back(in.d->factors.eta - in.a->factors.eta);
    }
  }
  out.tables.emplace_back("table1_instants.csv", instants);

  // Means beside the paper.
  Table means({"position", "part", "instant", "n", "quantity", "virtual_mean",
               "virtual_sd", "paper", "difference"});
  nlohmann::json claims = nlohmann::json::array();
  std::string md = fmt::format(
      "## Table 1: human factors at the instants of Fig. 9\n\n"
      "{} of {} cycles completed; each cell is the virtual mean over them, the paper's "
      "value in parentheses. a: first contact, b: largest tilt in contact, c: realigned "
      "(tilt below {} deg), d: completion. t is counted from the start of the cycle, as "
      "in the paper; A is in J (the paper prints kcal, docs/human-factors.md).\n\n"
      "| part | instant | n | V | f | eta | r | g | lambda_c | t (s) | A (J) | Psi_c |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
      completed, run.run.records.size(), scene.params.simulation.completion_angle_deg);
  std::string eta_data, xtics;
  for (std::size_t p = 0; p < n_parts; ++p) {
    const std::string& name = scene.parts[scene.sequence[p]].name;
    for (std::size_t k = 0; k < 4; ++k) {
      const experiment::Table1Row* ref =
          paper && p * 4 + k < paper->rows.size() ? &paper->rows[p * 4 + k] : nullptr;
      const std::size_t n = samples[p][k][0].size();
      std::string line = fmt::format("| {} | {} | {} |", name, kInstants[k], n);
      for (std::size_t c = 0; c < 9; ++c) {
        const stats::Summary s = stats::Summarize(samples[p][k][c]);
        const double paper_value = ref ? PaperValues(*ref)[c] : NAN;
        const double mean = s.mean.value_or(NAN);
        means.AddRow({static_cast<std::int64_t>(p), name, std::string(1, kInstants[k]),
                      static_cast<std::int64_t>(n), std::string(kColumns[c]), mean,
                      s.sd.value_or(NAN), paper_value, mean - paper_value});
        const int digits = c == 7 ? 1 : 2;
        line += n == 0 ? " - " : fmt::format(" {:.{}f}", mean, digits);
        if (ref) line += fmt::format(" ({:.{}f})", paper_value, c == 8 ? 1 : 2);
        line += " |";
      }
      md += line + "\n";
      const std::size_t x = p * 5 + k;
      xtics += fmt::format("{}'{}' {}", xtics.empty() ? "" : ", ",
                           k == 0 ? name + " a" : std::string(1, kInstants[k]), x);
      if (n > 0)
        eta_data += fmt::format("{} {} {}\n", x, stats::Mean(samples[p][k][2]),
                                ref ? ref->eta : NAN);
    }
    // Claim: eta rises from first contact to completion (paired over cycles).
    const std::vector<double>& rise = eta_rise[p];
    const std::string claim = "eta rises as the " + name + " nears its final position";
    const char* test = "paired t interval of eta(d) - eta(a) above 0";
    if (rise.size() < 2) {
      claims.push_back(UntestableClaim(
          claim, test,
          fmt::format("{} cycle(s) reached both instants a and d: the interval needs two",
                      rise.size())));
    } else {
      const stats::Interval ci = stats::MeanConfidenceInterval(rise);
      claims.push_back(
          Claim(claim, ci.lower > 0, test,
                fmt::format("eta(d) - eta(a) = {:.3f}, 95 % CI [{:.3f}, {:.3f}], "
                            "n = {}",
                            stats::Mean(rise), ci.lower, ci.upper, rise.size())));
    }
  }
  out.tables.emplace_back("table1_means.csv", means);
  out.summary = {{"completed_cycles", completed},
                 {"cycles", run.run.records.size()},
                 {"claims", claims}};
  out.markdown = md;
  out.plots.push_back(
      {"plots/table1_eta.png", "eta at the instants a-d of each part, virtual and paper",
       "$d << EOD\n" + eta_data +
           "EOD\nset title 'Table 1: vision coefficient eta at instants a-d'\n"
           "set ylabel 'eta'\nset yrange [0:1]\nset xtics (" +
           xtics +
           ") rotate by -30\nset key left top\nset grid\n"
           "plot $d using 1:2 with linespoints pt 7 title 'virtual (mean)', "
           "$d using 1:3 with linespoints pt 5 title 'paper'\n"});
  return out;
}

}  // namespace vahf::report
