// Paper Sec. 5.3 (Figs. 13-14): eta and lambda_c at fixed instants of the
// assembly under the general, best and worst working conditions.
#include <fmt/format.h>

#include "vahf/report/section.h"
#include "vahf/stats/summary.h"
#include "vahf/stats/welch.h"

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
  std::vector<std::vector<std::vector<double>>> eta(nc, std::vector<std::vector<double>>(ni)),
      lam = eta;
  std::vector<std::vector<double>> eta_all(nc), lam_all(nc);
  Table samples({"condition", "cycle", "paper_instant_s", "fraction", "cycle_time_s",
                 "virtual_time_s", "eta", "lambda_c"});
  for (const experiment::CycleRecord& r : d.records) {
    if (!r.result.completed) continue;
    for (std::size_t i = 0; i < ni; ++i) {
      const double fraction = file.instants_s[i] / file.paper_cycle_s;
      const double t = fraction * r.result.time;
      const human::FactorValues* f = FactorsAt(r.result, t);
      if (!f) continue;
      samples.AddRow({d.conditions[r.condition].name, static_cast<std::int64_t>(r.cycle),
                      file.instants_s[i], fraction, r.result.time, t, f->eta, f->lambda_c});
      eta[r.condition][i].push_back(f->eta);
      lam[r.condition][i].push_back(f->lambda_c);
      eta_all[r.condition].push_back(f->eta);
      lam_all[r.condition].push_back(f->lambda_c);
    }
  }
  out.tables.emplace_back("human_factors_groups_samples.csv", samples);

  Table means({"condition", "paper_instant_s", "quantity", "n", "mean", "ci_lower",
               "ci_upper"});
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
    for (std::size_t c = 0; c < nc; ++c) {
      fig_eta += fmt::format(" {}", stats::Summarize(eta[c][i]).mean.value_or(NAN));
      fig_lam += fmt::format(" {}", stats::Summarize(lam[c][i]).mean.value_or(NAN));
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
  if (general && best && worst) {
    for (const auto& [quantity, all] :
         {std::pair{"eta", &eta_all}, std::pair{"lambda_c", &lam_all}}) {
      const auto& g = (*all)[*general];
      const auto& b = (*all)[*best];
      const auto& w = (*all)[*worst];
      bool ok = g.size() >= 2 && b.size() >= 2 && w.size() >= 2;
      std::string evidence = "too few samples";
      if (ok) {
        const stats::WelchResult lo = stats::WelchTTest(b, g);
        const stats::WelchResult hi = stats::WelchTTest(g, w);
        ok = lo.mean_difference < 0 && lo.p_less < 0.05 && hi.mean_difference < 0 &&
             hi.p_less < 0.05;
        tests[quantity] = {{"mean_best", stats::Mean(b)},
                           {"mean_general", stats::Mean(g)},
                           {"mean_worst", stats::Mean(w)},
                           {"p_best_below_general", lo.p_less},
                           {"p_general_below_worst", hi.p_less}};
        evidence = fmt::format(
            "means best {:.3f}, general {:.3f}, worst {:.3f}; p(best < general) = {:.4f}, "
            "p(general < worst) = {:.4f}",
            stats::Mean(b), stats::Mean(g), stats::Mean(w), lo.p_less, hi.p_less);
      }
      claims.push_back(Claim(std::string(quantity) +
                                 " of the general condition lies between the best and "
                                 "the worst condition's",
                             ok, "two one-sided Welch t tests, 5 %", evidence));
    }
  }
  out.summary = {{"tests", tests}, {"claims", claims}};
  out.markdown = md;
  std::string plot_cols;
  for (std::size_t c = 0; c < nc; ++c)
    plot_cols += fmt::format("{}$d using 1:{} with linespoints title '{}'",
                             c ? ", " : "", c + 2, d.conditions[c].name);
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
