// Paper Sec. 5.3 (Figs. 13-14): eta and lambda_c at fixed instants of the
// assembly under the general, best and worst working conditions.
#include <fmt/format.h>

#include <array>
#include <map>
#include <optional>

#include "vahf/experiment/groups_input.h"
#include "vahf/report/figure.h"
#include "vahf/report/markdown.h"
#include "vahf/report/section.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

constexpr std::array<const char*, 2> kQuantities = {"eta", "lambda_c"};

// The factors in force at time `t` of a completed cycle: the last decision of
// the part being assembled then, at or before t.
const human::FactorValues* FactorsAt(const experiment::CycleResult& cycle, double t) {
  for (const experiment::PartRun& part : cycle.parts) {
    if (t > part.start_time + part.trial.end_time) continue;
    const sim::TraceRow* last = nullptr;
    for (const sim::TraceRow& row : part.trial.trace)
      if (part.start_time + row.time <= t) last = &row;
    return last ? &last->factors : nullptr;
  }
  return nullptr;
}

// eta and lambda_c at the paper's instants, taken at the same fraction of each
// completed cycle: the rows of the samples table, the values per quantity,
// condition and instant, and per condition each cycle's mean over the
// instants (cycles with every instant only), paired across conditions by the
// cycle's streams (common random numbers).
struct InstantFactors {
  Table rows{{"condition", "cycle", "paper_instant_s", "fraction", "cycle_time_s",
              "virtual_time_s", "eta", "lambda_c"}};
  // [quantity][condition][instant]
  std::array<std::vector<std::vector<std::vector<double>>>, 2> values;
  std::vector<std::map<std::uint64_t, std::array<double, 2>>> per_cycle;
};

void AddCycleFactors(const experiment::CycleRecord& r, const experiment::DesignRun& d,
                     const experiment::GroupsInput& file, InstantFactors* out) {
  const std::size_t ni = file.instants_s.size();
  std::array<double, 2> sum = {0, 0};
  std::size_t found = 0;
  for (std::size_t i = 0; i < ni; ++i) {
    const double fraction = file.instants_s[i] / file.paper_cycle_s;
    const double t = fraction * r.result.time;
    const human::FactorValues* f = FactorsAt(r.result, t);
    if (!f) continue;
    out->rows.AddRow({d.conditions[r.condition].name, static_cast<std::int64_t>(r.cycle),
                      file.instants_s[i], fraction, r.result.time, t, f->eta,
                      f->lambda_c});
    const std::array<double, 2> v = {f->eta, f->lambda_c};
    for (std::size_t q = 0; q < 2; ++q) {
      out->values[q][r.condition][i].push_back(v[q]);
      sum[q] += v[q];
    }
    ++found;
  }
  if (found == ni && ni > 0)
    out->per_cycle[r.condition][r.cycle] = {sum[0] / static_cast<double>(ni),
                                            sum[1] / static_cast<double>(ni)};
}

InstantFactors CollectFactors(const experiment::DesignRun& d,
                              const experiment::GroupsInput& file) {
  const std::size_t nc = d.conditions.size(), ni = file.instants_s.size();
  InstantFactors out;
  for (auto& v : out.values) v.assign(nc, std::vector<std::vector<double>>(ni));
  out.per_cycle.resize(nc);
  for (const experiment::CycleRecord& r : d.records)
    if (r.result.completed) AddCycleFactors(r, d, file, &out);
  return out;
}

// The means table and its Markdown: a row per condition and quantity, a
// column per instant.
void DescribeMeans(const experiment::DesignRun& d, const experiment::GroupsInput& file,
                   const InstantFactors& f, Section* out) {
  Table means(
      {"condition", "paper_instant_s", "quantity", "n", "mean", "ci_lower", "ci_upper"});
  std::vector<std::string> headings = {"condition", "quantity"};
  for (double t : file.instants_s) headings.push_back(fmt::format("{:g} s", t));
  MarkdownTable md(std::move(headings));
  for (std::size_t c = 0; c < d.conditions.size(); ++c)
    for (std::size_t q = 0; q < 2; ++q) {
      std::vector<std::string> cells = {d.conditions[c].name, kQuantities[q]};
      for (std::size_t i = 0; i < file.instants_s.size(); ++i) {
        const stats::Summary s = stats::Summarize(f.values[q][c][i]);
        means.AddRow({d.conditions[c].name, file.instants_s[i],
                      std::string(kQuantities[q]), static_cast<std::int64_t>(s.n),
                      s.mean.value_or(NAN), s.ci ? s.ci->lower : NAN,
                      s.ci ? s.ci->upper : NAN});
        cells.push_back(s.mean ? fmt::format("{:.3f}", *s.mean) : "-");
      }
      md.AddRow(std::move(cells));
    }
  out->tables.emplace_back("human_factors_groups_means.csv", std::move(means));
  out->markdown =
      fmt::format(
          "## Human factors under three working conditions (Sec. 5.3, Figs. 13-14)\n\n"
          "eta and lambda_c at {} of the paper's {:g} s assembly, taken at the same "
          "fraction of each completed virtual cycle (the operator's decision in force "
          "then); mean and 95 % interval.\n\n",
          fmt::join(file.instants_s, ", "), file.paper_cycle_s) +
      ToMarkdown(md);
}

// Figs. 13-14: a quantity at each instant, a line per condition with each
// mean's 95 % interval (the mean alone when one sample gives no interval).
Plot QuantityPlot(const experiment::DesignRun& d, const experiment::GroupsInput& file,
                  const InstantFactors& f, std::size_t q) {
  const char* what = kQuantities[q];
  const char* fig = q == 0 ? "Fig. 13" : "Fig. 14";
  std::vector<DataRow> rows;
  for (std::size_t i = 0; i < file.instants_s.size(); ++i) {
    DataRow row = DataRow().Short(file.instants_s[i]);
    for (std::size_t c = 0; c < d.conditions.size(); ++c)
      row.MeanAndInterval(stats::Summarize(f.values[q][c][i]));
    rows.push_back(row);
  }
  Figure figure;
  figure.Data("d", rows)
      .Title(fmt::format("{}: {} at the paper instants", fig, what))
      .XLabel("paper instant (s of 16)")
      .YLabel(what)
      .Set("yrange [0:1]")
      .Set("grid")
      .Set("key left top");
  for (std::size_t c = 0; c < d.conditions.size(); ++c)
    figure.Draw({"$d", fmt::format("1:{}:{}:{}", 3 * c + 2, 3 * c + 3, 3 * c + 4),
                 "with yerrorlines", d.conditions[c].name});
  return {fmt::format("plots/human_factors_{}.png", what),
          q == 0 ? "Fig. 13: vision coefficient eta per working condition"
                 : "Fig. 14: comfort coefficient lambda_c per working condition",
          GnuplotScript(figure)};
}

// Quantity q of conditions a and b over the cycles both have, in cycle order.
std::pair<std::vector<double>, std::vector<double>> Paired(const InstantFactors& f,
                                                           std::size_t a, std::size_t b,
                                                           std::size_t q) {
  std::pair<std::vector<double>, std::vector<double>> out;
  for (const auto& [cycle, values] : f.per_cycle[a]) {
    const auto it = f.per_cycle[b].find(cycle);
    if (it == f.per_cycle[b].end()) continue;
    out.first.push_back(values[q]);
    out.second.push_back(it->second[q]);
  }
  return out;
}

std::optional<std::size_t> ConditionIndex(const experiment::DesignRun& d,
                                          const std::string& name) {
  for (std::size_t c = 0; c < d.conditions.size(); ++c)
    if (d.conditions[c].name == name) return c;
  return std::nullopt;
}

// Claim (Sec. 5.3): quantity q of the general condition lies between the best
// and the worst condition's (pooled over the instants).
nlohmann::json BetweenClaim(const experiment::DesignRun& d, const InstantFactors& f,
                            std::size_t q, nlohmann::json* tests) {
  const std::string claim = std::string(kQuantities[q]) +
                            " of the general condition lies between the best and the "
                            "worst condition's";
  const char* test =
      "two paired t tests over the cycles' means across the instants, one-sided, 5 %";
  const auto general = ConditionIndex(d, "general"), best = ConditionIndex(d, "best"),
             worst = ConditionIndex(d, "worst");
  if (!general || !best || !worst)
    return UntestableClaim(
        claim, test, "the experiment needs conditions named general, best and worst");
  const auto [b, g] = Paired(f, *best, *general, q);
  const auto [g2, w] = Paired(f, *general, *worst, q);
  std::string why;
  const auto lo = PairedIfDefined(b, g, "cycles completed under best and general", &why);
  const auto hi =
      lo ? PairedIfDefined(g2, w, "cycles completed under general and worst", &why)
         : std::nullopt;
  if (!lo || !hi) return UntestableClaim(claim, test, why);
  (*tests)[kQuantities[q]] = {{"best_minus_general", lo->mean_difference},
                              {"general_minus_worst", hi->mean_difference},
                              {"pairs_best_general", lo->n},
                              {"pairs_general_worst", hi->n},
                              {"p_best_below_general", lo->p_less},
                              {"p_general_below_worst", hi->p_less}};
  const bool ok = lo->mean_difference < 0 && lo->p_less < 0.05 &&
                  hi->mean_difference < 0 && hi->p_less < 0.05;
  return Claim(
      claim, ok, test,
      fmt::format("best - general = {:.3f} [{:.3f}, {:.3f}] (p(best < general) = "
                  "{:.4f}, {} pairs), general - worst = {:.3f} [{:.3f}, {:.3f}] "
                  "(p(general < worst) = {:.4f}, {} pairs)",
                  lo->mean_difference, lo->ci.lower, lo->ci.upper, lo->p_less, lo->n,
                  hi->mean_difference, hi->ci.lower, hi->ci.upper, hi->p_less, hi->n));
}

}  // namespace

Section HumanFactorsGroupsSection(const experiment::ExperimentRun& run) {
  const experiment::DesignRun& d = run.run;
  const experiment::GroupsInput& groups = run.file->Input<experiment::GroupsInput>();
  const InstantFactors factors = CollectFactors(d, groups);
  Section out;
  out.tables.emplace_back("human_factors_groups_cycles.csv", CyclesTable(d));
  out.tables.emplace_back("human_factors_groups_samples.csv", factors.rows);
  DescribeMeans(d, groups, factors, &out);
  nlohmann::json claims = nlohmann::json::array();
  nlohmann::json tests = nlohmann::json::object();
  for (std::size_t q = 0; q < kQuantities.size(); ++q) {
    claims.push_back(BetweenClaim(d, factors, q, &tests));
    out.plots.push_back(QuantityPlot(d, groups, factors, q));
  }
  out.summary = {{"tests", tests}, {"claims", claims}};
  return out;
}

}  // namespace vahf::report
