// Paper Table 1: the factors at instants a-d of each part, virtual beside the
// paper's, and the claim that eta rises as the part nears its final position.
#include <fmt/format.h>

#include <array>

#include "vahf/experiment/instants.h"
#include "vahf/experiment/table1_input.h"
#include "vahf/experiment/table1_reference.h"
#include "vahf/report/figure.h"
#include "vahf/report/markdown.h"
#include "vahf/report/section.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

constexpr std::array<char, 4> kInstants = {'a', 'b', 'c', 'd'};
constexpr std::size_t kEta = 2;  // eta's place among the nine quantities
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

// Every instant of every completed cycle: the rows of table1_instants.csv,
// the samples of each quantity per part and instant, and eta(d) - eta(a) of
// each cycle per part (the claim's pairs).
struct InstantSamples {
  Table rows{{"cycle", "position", "part", "instant", "V", "f", "eta", "r", "g",
              "lambda_c", "t_s", "A_J", "psi"}};
  std::vector<std::array<std::array<std::vector<double>, 9>, 4>> values;
  std::vector<std::vector<double>> eta_rise;
  int completed = 0;
};

void AddPartInstants(const experiment::CycleRecord& r, std::size_t p,
                     const scene::Scene& scene, InstantSamples* out) {
  const experiment::PartRun& part = r.result.parts[p];
  const scene::Part& sp = scene.parts[scene.sequence[p]];
  const experiment::Instants in = experiment::FindInstants(
      part.trial, sp.target.Rotation(), scene.params.simulation.completion_angle_deg);
  const std::array<const std::optional<sim::TraceRow>*, 4> rows = {&in.a, &in.b, &in.c,
                                                                   &in.d};
  for (std::size_t k = 0; k < 4; ++k) {
    if (!*rows[k]) continue;
    const auto v = Values(**rows[k], part);
    std::vector<Table::Cell> cells = {static_cast<std::int64_t>(r.cycle),
                                      static_cast<std::int64_t>(p), sp.name,
                                      std::string(1, kInstants[k])};
    for (std::size_t c = 0; c < 9; ++c) {
      cells.emplace_back(std::in_place_type<double>, v[c]);
      out->values[p][k][c].push_back(v[c]);
    }
    out->rows.AddRow(std::move(cells));
  }
  if (in.a && in.d) out->eta_rise[p].push_back(in.d->factors.eta - in.a->factors.eta);
}

InstantSamples CollectInstants(const experiment::DesignRun& d,
                               const scene::Scene& scene) {
  InstantSamples out;
  const std::size_t n_parts = scene.sequence.size();
  out.values.resize(n_parts);
  out.eta_rise.resize(n_parts);
  for (const experiment::CycleRecord& r : d.records) {
    if (!r.result.completed) continue;
    ++out.completed;
    for (std::size_t p = 0; p < n_parts; ++p) AddPartInstants(r, p, scene, &out);
  }
  return out;
}

// The paper's row for part p at instant k, if the paper table has it.
const experiment::Table1Row* PaperRow(const std::optional<experiment::Table1>& paper,
                                      std::size_t p, std::size_t k) {
  return paper && p * 4 + k < paper->rows.size() ? &paper->rows[p * 4 + k] : nullptr;
}

// The virtual mean of each quantity, the paper's in parentheses; A to one
// decimal, the paper's Psi_c to one.
std::vector<std::string> MeansRow(const std::string& part, std::size_t k,
                                  const std::array<std::vector<double>, 9>& values,
                                  const experiment::Table1Row* ref) {
  const std::size_t n = values[0].size();
  std::vector<std::string> cells = {part, std::string(1, kInstants[k]),
                                    std::to_string(n)};
  for (std::size_t c = 0; c < 9; ++c) {
    std::string cell =
        n == 0 ? "- " : fmt::format("{:.{}f}", stats::Mean(values[c]), c == 7 ? 1 : 2);
    if (ref) cell += fmt::format(" ({:.{}f})", PaperValues(*ref)[c], c == 8 ? 1 : 2);
    cells.push_back(cell);
  }
  return cells;
}

void AddMeansRows(const std::string& part, std::size_t p, std::size_t k,
                  const std::array<std::vector<double>, 9>& values,
                  const experiment::Table1Row* ref, Table* means) {
  const std::size_t n = values[0].size();
  for (std::size_t c = 0; c < 9; ++c) {
    const stats::Summary s = stats::Summarize(values[c]);
    const double paper_value = ref ? PaperValues(*ref)[c] : NAN;
    const double mean = s.mean.value_or(NAN);
    means->AddRow({static_cast<std::int64_t>(p), part, std::string(1, kInstants[k]),
                   static_cast<std::int64_t>(n), std::string(kColumns[c]), mean,
                   s.sd.value_or(NAN), paper_value, mean - paper_value});
  }
}

// Claim: eta rises from first contact to completion (paired over cycles).
nlohmann::json EtaRiseClaim(const std::string& part, const std::vector<double>& rise) {
  const std::string claim = "eta rises as the " + part + " nears its final position";
  const char* test = "paired t interval of eta(d) - eta(a) above 0";
  if (rise.size() < 2)
    return UntestableClaim(
        claim, test,
        fmt::format("{} cycle(s) reached both instants a and d: the interval needs two",
                    rise.size()));
  const stats::Interval ci = stats::MeanConfidenceInterval(rise);
  return Claim(claim, ci.lower > 0, test,
               fmt::format("eta(d) - eta(a) = {:.3f}, 95 % CI [{:.3f}, {:.3f}], n = {}",
                           stats::Mean(rise), ci.lower, ci.upper, rise.size()));
}

// eta at each instant, virtual mean and paper, a part's instants side by side.
Figure EtaFigure(const std::vector<std::string>& parts, const InstantSamples& samples,
                 const std::optional<experiment::Table1>& paper) {
  std::vector<DataRow> rows;
  std::string xtics;
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t x = p * 5 + k;
      xtics += fmt::format("{}'{}' {}", xtics.empty() ? "" : ", ",
                           k == 0 ? parts[p] + " a" : std::string(1, kInstants[k]), x);
      const std::vector<double>& eta = samples.values[p][k][kEta];
      const experiment::Table1Row* ref = PaperRow(paper, p, k);
      if (!eta.empty())
        rows.push_back(DataRow()
                           .Integer(static_cast<std::int64_t>(x))
                           .Number(stats::Mean(eta))
                           .Number(ref ? ref->eta : NAN));
    }
  Figure f;
  f.Data("d", rows)
      .Title("Table 1: vision coefficient eta at instants a-d")
      .YLabel("eta")
      .Set("yrange [0:1]")
      .Set("xtics (" + xtics + ") rotate by -30")
      .Set("key left top")
      .Set("grid")
      .Draw({"$d", "1:2", "with linespoints pt 7", "virtual (mean)"})
      .Draw({"$d", "1:3", "with linespoints pt 5", "paper"});
  return f;
}

// What the table shows: the instants, the units, how many cycles it covers.
std::string Table1Intro(const experiment::ExperimentRun& run, int completed) {
  return fmt::format(
      "## Table 1: human factors at the instants of Fig. 9\n\n"
      "{} of {} cycles completed; each cell is the virtual mean over them, the paper's "
      "value in parentheses. a: first contact, b: largest tilt in contact, c: "
      "realigned (tilt below {} deg), d: completion. t is counted from the start of "
      "the cycle, as in the paper; A is in J (the paper prints kcal, "
      "docs/human-factors.md).\n\n",
      completed, run.run.records.size(),
      run.file->scene.params.simulation.completion_angle_deg);
}

}  // namespace

Section Table1Section(const experiment::ExperimentRun& run) {
  const scene::Scene& scene = run.file->scene;
  std::optional<experiment::Table1> paper;
  const std::string& table = run.file->Input<experiment::Table1Input>().paper_table_path;
  if (!table.empty()) paper = experiment::LoadTable1(table);
  const InstantSamples samples = CollectInstants(run.run, scene);
  std::vector<std::string> parts;
  for (std::size_t i : scene.sequence) parts.push_back(scene.parts[i].name);

  Table means({"position", "part", "instant", "n", "quantity", "virtual_mean",
               "virtual_sd", "paper", "difference"});
  MarkdownTable md{{"part", "instant", "n", "V", "f", "eta", "r", "g", "lambda_c",
                    "t (s)", "A (J)", "Psi_c"}};
  nlohmann::json claims = nlohmann::json::array();
  for (std::size_t p = 0; p < parts.size(); ++p) {
    for (std::size_t k = 0; k < 4; ++k) {
      const auto& values = samples.values[p][k];
      AddMeansRows(parts[p], p, k, values, PaperRow(paper, p, k), &means);
      md.AddRow(MeansRow(parts[p], k, values, PaperRow(paper, p, k)));
    }
    claims.push_back(EtaRiseClaim(parts[p], samples.eta_rise[p]));
  }
  Section out;
  out.tables = {{"table1_cycles.csv", CyclesTable(run.run)},
                {"table1_instants.csv", samples.rows},
                {"table1_means.csv", means}};
  out.summary = {{"completed_cycles", samples.completed},
                 {"cycles", run.run.records.size()},
                 {"claims", claims}};
  out.markdown = Table1Intro(run, samples.completed) + ToMarkdown(md);
  out.plots.push_back({"plots/table1_eta.png",
                       "eta at the instants a-d of each part, virtual and paper",
                       GnuplotScript(EtaFigure(parts, samples, paper))});
  return out;
}

}  // namespace vahf::report
