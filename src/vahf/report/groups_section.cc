// Paper Sec. 5.3 (Figs. 13-14): eta and lambda_c at fixed instants of the
// assembly under the general, best and worst working conditions.
#include <fmt/format.h>

#include <map>

#include "vahf/report/section.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

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

}  // namespace

Section HumanFactorsGroupsSection(const experiment::ExperimentRun& run) {
  const scene::ExperimentFile& file = *run.file;
  const experiment::DesignRun& d = run.run;
  Section out;
  out.kind = "human_factors_groups";
  out.tables.emplace_back("human_factors_groups_cycles.csv", CyclesTable(d));

  const std::size_t nc = d.conditions.size(), ni = file.instants_s.size();
  // [condition][instant] samples of eta and lambda_c, and pooled per condition.
  std::vector<std::vector<std::vector<double>>> eta(nc,
                                                    std::vector<std::vector<double>>(ni)),
      lam = eta;
  // Per condition, cycle -> the mean over the instants of eta and lambda_c
  // (cycles with every instant only): one value per cycle, paired across
  // conditions by the cycle's streams (common random numbers).
  std::vector<std::map<std::uint64_t, std::pair<double, double>>> per_cycle(nc);
  Table samples({"condition", "cycle", "paper_instant_s", "fraction", "cycle_time_s",
                 "virtual_time_s", "eta", "lambda_c"});
  for (const experiment::CycleRecord& r : d.records) {
    if (!r.result.completed) continue;
    double eta_sum = 0, lam_sum = 0;
    std::size_t found = 0;
    for (std::size_t i = 0; i < ni; ++i) {
      const double fraction = file.instants_s[i] / file.paper_cycle_s;
      const double t = fraction * r.result.time;
      const human::FactorValues* f = FactorsAt(r.result, t);
      if (!f) continue;
      samples.AddRow({d.conditions[r.condition].name, static_cast<std::int64_t>(r.cycle),
                      file.instants_s[i], fraction, r.result.time, t, f->eta,
                      f->lambda_c});
      eta[r.condition][i].push_back(f->eta);
      lam[r.condition][i].push_back(f->lambda_c);
      eta_sum += f->eta;
      lam_sum += f->lambda_c;
      ++found;
    }
    if (found == ni && ni > 0)
      per_cycle[r.condition][r.cycle] = {eta_sum / static_cast<double>(ni),
                                         lam_sum / static_cast<double>(ni)};
  }
  out.tables.emplace_back("human_factors_groups_samples.csv", samples);

  Table means(
      {"condition", "paper_instant_s", "quantity", "n", "mean", "ci_lower", "ci_upper"});
  std::string md = fmt::format(
      "## Human factors under three working conditions (Sec. 5.3, Figs. 13-14)\n\n"
      "eta and lambda_c at {} of the paper's {:g} s assembly, taken at the same fraction "
      "of each completed virtual cycle (the operator's decision in force then); mean and "
      "95 % interval.\n\n| condition | quantity |",
      fmt::join(file.instants_s, ", "), file.paper_cycle_s);
  for (double t : file.instants_s) md += fmt::format(" {:g} s |", t);
  md += "\n| --- | --- |";
  for (std::size_t i = 0; i < ni; ++i) md += " --- |";
  md += "\n";
  std::string fig_eta, fig_lam;
  for (std::size_t i = 0; i < ni; ++i) {
    fig_eta += fmt::format("{:g}", file.instants_s[i]);
    fig_lam += fmt::format("{:g}", file.instants_s[i]);
    // Each condition's mean with its 95 % interval (the mean alone when one
    // sample gives no interval; NaN, not drawn, when none).
    const auto point = [](const std::vector<double>& xs) {
      const stats::Summary m = stats::Summarize(xs);
      const double mean = m.mean.value_or(NAN);
      return fmt::format(" {} {} {}", mean, m.ci ? m.ci->lower : mean,
                         m.ci ? m.ci->upper : mean);
    };
    for (std::size_t c = 0; c < nc; ++c) {
      fig_eta += point(eta[c][i]);
      fig_lam += point(lam[c][i]);
    }
    fig_eta += "\n";
    fig_lam += "\n";
  }
  for (std::size_t c = 0; c < nc; ++c) {
    for (const auto& [quantity, values] :
         {std::pair{"eta", &eta[c]}, std::pair{"lambda_c", &lam[c]}}) {
      md += fmt::format("| {} | {} |", d.conditions[c].name, quantity);
      for (std::size_t i = 0; i < ni; ++i) {
        const stats::Summary s = stats::Summarize((*values)[i]);
        means.AddRow({d.conditions[c].name, file.instants_s[i], std::string(quantity),
                      static_cast<std::int64_t>(s.n), s.mean.value_or(NAN),
                      s.ci ? s.ci->lower : NAN, s.ci ? s.ci->upper : NAN});
        md += s.mean ? fmt::format(" {:.3f} |", *s.mean) : " - |";
      }
      md += "\n";
    }
  }
  out.tables.emplace_back("human_factors_groups_means.csv", means);

  // Claim (Sec. 5.3): the general condition lies between the best and the
  // worst, for eta and for lambda_c (pooled over the instants).
  nlohmann::json claims = nlohmann::json::array();
  nlohmann::json tests = nlohmann::json::object();
  const auto index = [&](const std::string& name) -> std::optional<std::size_t> {
    for (std::size_t c = 0; c < nc; ++c)
      if (d.conditions[c].name == name) return c;
    return std::nullopt;
  };
  const auto general = index("general"), best = index("best"), worst = index("worst");
  // a's and b's values of `quantity` (0: eta, 1: lambda_c) over the cycles
  // both have, in cycle order.
  const auto pairs = [&](std::size_t a, std::size_t b, int quantity) {
    std::pair<std::vector<double>, std::vector<double>> paired;
    for (const auto& [cycle, values] : per_cycle[a]) {
      const auto it = per_cycle[b].find(cycle);
      if (it == per_cycle[b].end()) continue;
      paired.first.push_back(quantity == 0 ? values.first : values.second);
      paired.second.push_back(quantity == 0 ? it->second.first : it->second.second);
    }
    return paired;
  };
  int q = 0;
  for (const char* quantity : {"eta", "lambda_c"}) {
    const int index_q = q++;
    const std::string claim = std::string(quantity) +
                              " of the general condition lies between the best and the "
                              "worst condition's";
    const char* test =
        "two paired t tests over the cycles' means across the instants, one-sided, 5 %";
    if (!general || !best || !worst) {
      claims.push_back(UntestableClaim(
          claim, test, "the experiment needs conditions named general, best and worst"));
      continue;
    }
    const auto [b, g] = pairs(*best, *general, index_q);
    const auto [g2, w] = pairs(*general, *worst, index_q);
    std::string why;
    const auto lo =
        PairedIfDefined(b, g, "cycles completed under best and general", &why);
    const auto hi =
        lo ? PairedIfDefined(g2, w, "cycles completed under general and worst", &why)
           : std::nullopt;
    if (!lo || !hi) {
      claims.push_back(UntestableClaim(claim, test, why));
      continue;
    }
    const bool ok = lo->mean_difference < 0 && lo->p_less < 0.05 &&
                    hi->mean_difference < 0 && hi->p_less < 0.05;
    tests[quantity] = {{"best_minus_general", lo->mean_difference},
                       {"general_minus_worst", hi->mean_difference},
                       {"pairs_best_general", lo->n},
                       {"pairs_general_worst", hi->n},
                       {"p_best_below_general", lo->p_less},
                       {"p_general_below_worst", hi->p_less}};
    claims.push_back(
        Claim(claim, ok, test,
              fmt::format(
                  "best - general = {:.3f} [{:.3f}, {:.3f}] (p(best < general) = {:.4f}, "
                  "{} pairs), general - worst = {:.3f} [{:.3f}, {:.3f}] (p(general < "
                  "worst) = {:.4f}, {} pairs)",
                  lo->mean_difference, lo->ci.lower, lo->ci.upper, lo->p_less, lo->n,
                  hi->mean_difference, hi->ci.lower, hi->ci.upper, hi->p_less, hi->n)));
  }
  out.summary = {{"tests", tests}, {"claims", claims}};
  out.markdown = md;
  std::string plot_cols;
  for (std::size_t c = 0; c < nc; ++c)
    plot_cols +=
        fmt::format("{}$d using 1:{}:{}:{} with yerrorlines title '{}'", c ? ", " : "",
                    3 * c + 2, 3 * c + 3, 3 * c + 4, d.conditions[c].name);
  const auto figure = [&](const std::string& data, const char* what, const char* fig) {
    return "$d << EOD\n" + data + "EOD\nset title '" + fig + ": " + what +
           " at the paper instants'\nset xlabel 'paper instant (s of 16)'\nset ylabel '" +
           what + "'\nset yrange [0:1]\nset grid\nset key left top\nplot " + plot_cols +
           "\n";
  };
  out.plots.push_back({"plots/human_factors_eta.png",
                       "Fig. 13: vision coefficient eta per working condition",
                       figure(fig_eta, "eta", "Fig. 13")});
  out.plots.push_back({"plots/human_factors_lambda_c.png",
                       "Fig. 14: comfort coefficient lambda_c per working condition",
                       figure(fig_lam, "lambda_c", "Fig. 14")});
  return out;
}

}  // namespace vahf::report
