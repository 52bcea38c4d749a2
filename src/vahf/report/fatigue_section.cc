// Paper Sec. 5.4 (Figs. 15-16): mean assembly time and assembly success rate
// in each segment of an hour's work, and whether they worsen.
#include <fmt/format.h>

#include <map>

#include "vahf/human/fatigue.h"
#include "vahf/report/section.h"
#include "vahf/stats/proportion.h"
#include "vahf/stats/summary.h"

namespace vahf::report {

Section FatigueSection(const experiment::ExperimentRun& run) {
  const scene::Scene& scene = run.file->scene;
  const experiment::DesignRun& d = run.run;
  Section out;
  out.kind = "fatigue";
  out.tables.emplace_back("fatigue_cycles.csv", CyclesTable(d));
  out.tables.emplace_back("fatigue_pilot_cycles.csv", CyclesTable(run.pilot));

  const std::size_t ns = d.conditions.size();
  std::vector<std::vector<double>> times(ns);
  std::vector<stats::Count> counts(ns);
  std::vector<std::int64_t> numerical(ns, 0);
  for (const experiment::CycleRecord& r : d.records) {
    if (r.result
            .numerical_failure) {  // a failure of the computation, not of the assembly
      ++numerical[r.condition];
      continue;
    }
    ++counts[r.condition].trials;
    if (!r.result.completed) continue;
    ++counts[r.condition].successes;
    times[r.condition].push_back(r.result.time);
  }
  const double a_max = scene.params.fatigue.a_max;
  Table segments({"segment", "minute_start", "minute_end", "work_start_J", "work_end_J",
                  "psi_start", "psi_end", "cycles", "completed", "numerical_failures",
                  "success_rate", "wilson_lower", "wilson_upper", "mean_time_s",
                  "ci_lower_s", "ci_upper_s"});
  std::string md = fmt::format(
      "## Fatigue over one hour (Sec. 5.4, Figs. 15-16)\n\n"
      "Work rate from {} pilot cycles at A = 0: {:.4g} J per second of assembly. Each "
      "segment's cycles start with the work back-to-back cycles would have done by their "
      "minute; Psi_c = (A_max - A) / A_max with A_max = {:.4g} J (Eq. 6). Success rate "
      "with "
      "its 95 % Wilson interval, over the cycles that ended without a numerical failure "
      "(those say nothing about the assembly: see Numerical health); mean time of "
      "completed cycles with its 95 % t interval.\n\n"
      "| segment | A at start (J) | Psi_c at start | Psi_c at end | success rate | mean "
      "time "
      "(s) |\n| --- | --- | --- | --- | --- | --- |\n",
      run.pilot.records.size(), run.work_rate, a_max);
  std::string fig15, fig16;
  for (std::size_t s = 0; s < ns; ++s) {
    const experiment::Condition& c = d.conditions[s];
    const stats::Interval w = stats::WilsonInterval(counts[s]);
    const stats::Summary t = stats::Summarize(times[s]);
    const double rate = counts[s].trials ? static_cast<double>(counts[s].successes) /
                                               static_cast<double>(counts[s].trials)
                                         : NAN;
    const double psi0 = human::FatigueCoefficient(c.work_start, a_max);
    const double psi1 = human::FatigueCoefficient(c.work_end, a_max);
    segments.AddRow({c.name, c.minute_start, c.minute_end, c.work_start, c.work_end, psi0,
                     psi1, counts[s].trials, counts[s].successes, numerical[s], rate,
                     w.lower, w.upper, t.mean.value_or(NAN), t.ci ? t.ci->lower : NAN,
                     t.ci ? t.ci->upper : NAN});
    md += fmt::format(
        "| {} | {:.4g} | {:.5f} | {:.5f} | {}/{} = {:.2f} [{:.2f}, {:.2f}] | "
        "{} |\n",
        c.name, c.work_start, psi0, psi1, counts[s].successes, counts[s].trials, rate,
        w.lower, w.upper, MeanCi(t));
    const double mid = 0.5 * (c.minute_start + c.minute_end);
    if (t.mean)
      fig15 += fmt::format("{} {} {} {}\n", mid, *t.mean, t.ci ? t.ci->lower : *t.mean,
                           t.ci ? t.ci->upper : *t.mean);
    fig16 += fmt::format("{} {} {} {}\n", mid, rate, w.lower, w.upper);
  }
  out.tables.emplace_back("fatigue_segments.csv", segments);

  nlohmann::json claims = nlohmann::json::array();
  nlohmann::json tests = nlohmann::json::object();
  // Segment s's cycle j runs on the streams of every segment's cycle j (common
  // random numbers): the first and last segments' cycles are pairs.
  const char* kTimeClaim = "mean assembly time rises from the first to the last segment";
  const char* kTimeTest =
      "paired t test over the cycles completed in both segments, one-sided (last > "
      "first), "
      "5 %";
  const char* kRateClaim =
      "the assembly success rate falls from the first to the last segment (paper: 0.96 "
      "to "
      "0.75)";
  const char* kRateTest =
      "McNemar's exact test over the cycles paired across the segments, one-sided (rate "
      "fell), 5 %";
  if (ns < 2) {
    const std::string why =
        fmt::format("the run has {} segment(s): a trend needs two", ns);
    claims.push_back(UntestableClaim(kTimeClaim, kTimeTest, why));
    claims.push_back(UntestableClaim(kRateClaim, kRateTest, why));
  } else {
    const std::size_t last = ns - 1;
    std::map<std::uint64_t, const experiment::CycleResult*> first_by_cycle;
    for (const experiment::CycleRecord& r : d.records)
      if (r.condition == 0 && !r.result.numerical_failure)
        first_by_cycle[r.cycle] = &r.result;
    std::vector<double> last_times, first_times;
    std::int64_t fell = 0, rose = 0, pairs = 0;
    for (const experiment::CycleRecord& r : d.records) {
      if (r.condition != last || r.result.numerical_failure) continue;
      const auto it = first_by_cycle.find(r.cycle);
      if (it == first_by_cycle.end()) continue;
      const experiment::CycleResult& before = *it->second;
      ++pairs;
      fell += before.completed && !r.result.completed;
      rose += !before.completed && r.result.completed;
      if (before.completed && r.result.completed) {
        last_times.push_back(r.result.time);
        first_times.push_back(before.time);
      }
    }
    std::string why;
    if (const auto w = PairedIfDefined(last_times, first_times,
                                       "cycles completed in both segments", &why)) {
      tests["time_last_minus_first"] = {{"pairs", w->n},
                                        {"mean_difference_s", w->mean_difference},
                                        {"ci_lower_s", w->ci.lower},
                                        {"ci_upper_s", w->ci.upper},
                                        {"p_greater", w->p_greater}};
      claims.push_back(Claim(
          kTimeClaim, w->mean_difference > 0 && w->p_greater < 0.05, kTimeTest,
          fmt::format("last - first = {:.4f} s over {} paired cycles, 95 % CI [{:.4f}, "
                      "{:.4f}], p = {:.4f}",
                      w->mean_difference, w->n, w->ci.lower, w->ci.upper, w->p_greater)));
    } else {
      claims.push_back(UntestableClaim(kTimeClaim, kTimeTest, why));
    }
    const double p = stats::McNemarRateFellP(fell, rose);
    tests["success_first"] = {{"successes", counts[0].successes},
                              {"cycles", counts[0].trials}};
    tests["success_last"] = {{"successes", counts[last].successes},
                             {"cycles", counts[last].trials}};
    tests["paired_cycles"] = pairs;
    tests["pairs_succeeded_then_failed"] = fell;
    tests["pairs_failed_then_succeeded"] = rose;
    tests["p_rate_fell"] = p;
    claims.push_back(Claim(
        kRateClaim, p < 0.05, kRateTest,
        fmt::format(
            "{}/{} then {}/{}; of {} paired cycles {} succeeded then failed and {} "
            "failed then succeeded, p = {:.4f}; Psi_c at the end of the hour {:.5f}",
            counts[0].successes, counts[0].trials, counts[last].successes,
            counts[last].trials, pairs, fell, rose, p,
            human::FatigueCoefficient(d.conditions[last].work_end, a_max))));
  }
  out.summary = {
      {"work_rate_J_per_s", run.work_rate},
      {"a_max_J", a_max},
      {"psi_end_of_hour",
       ns ? human::FatigueCoefficient(d.conditions[ns - 1].work_end, a_max) : 1.0},
      {"tests", tests},
      {"claims", claims}};
  out.markdown = md;
  out.plots.push_back(
      {"plots/fatigue_time.png", "Fig. 15: mean assembly time in each segment",
       "$d << EOD\n" + fig15 +
           "EOD\nset title 'Fig. 15: mean assembly time per segment'\n"
           "set xlabel 'minute of work'\nset ylabel 'time (s)'\nset grid\nset xrange "
           "[0:" +
           fmt::format("{:g}", run.file->fatigue.duration_min) +
           "]\nplot $d using 1:2:3:4 with yerrorlines pt 7 title 'virtual'\n"});
  out.plots.push_back(
      {"plots/fatigue_success.png", "Fig. 16: assembly success rate in each segment",
       "$d << EOD\n" + fig16 + "EOD\n$p << EOD\n" +
           fmt::format(
               "{:g} 0.96\n{:g} 0.75\n",
               0.5 * run.file->fatigue.duration_min / static_cast<double>(ns),
               run.file->fatigue.duration_min * (1 - 0.5 / static_cast<double>(ns))) +
           "EOD\n"
           "set title 'Fig. 16: assembly success rate per segment'\n"
           "set xlabel 'minute of work'\nset ylabel 'success rate'\nset yrange [0:1.05]\n"
           "set grid\nset key left bottom\nset xrange [0:" +
           fmt::format("{:g}", run.file->fatigue.duration_min) +
           "]\nplot $d using 1:2:3:4 with yerrorlines pt 7 title 'virtual (Wilson 95 "
           "%)', "
           "$p using 1:2 with points pt 5 ps 1.5 title 'paper, virtual (first, "
           "last)'\n"});
  return out;
}

}  // namespace vahf::report
