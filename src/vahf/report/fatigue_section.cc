// Paper Sec. 5.4 (Figs. 15-16): mean assembly time and assembly success rate
// in each segment of an hour's work, and whether they worsen.
#include <fmt/format.h>

#include <map>

#include "vahf/experiment/fatigue_input.h"
#include "vahf/human/fatigue.h"
#include "vahf/report/figure.h"
#include "vahf/report/markdown.h"
#include "vahf/report/section.h"
#include "vahf/stats/proportion.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

// Per segment: the cycles that ended without a numerical failure (trials) and
// those completed (successes), the completed cycles' times, and the numerical
// failures (a failure of the computation, not of the assembly).
struct SegmentOutcomes {
  std::vector<std::vector<double>> times;
  std::vector<stats::Count> counts;
  std::vector<std::int64_t> numerical;
};

SegmentOutcomes CountSegments(const experiment::DesignRun& d) {
  const std::size_t ns = d.conditions.size();
  SegmentOutcomes o{std::vector<std::vector<double>>(ns), std::vector<stats::Count>(ns),
                    std::vector<std::int64_t>(ns, 0)};
  for (const experiment::CycleRecord& r : d.records) {
    if (r.result.numerical_failure) {
      ++o.numerical[r.condition];
      continue;
    }
    ++o.counts[r.condition].trials;
    if (!r.result.completed) continue;
    ++o.counts[r.condition].successes;
    o.times[r.condition].push_back(r.result.time);
  }
  return o;
}

double SuccessRate(const stats::Count& c) {
  return c.trials ? static_cast<double>(c.successes) / static_cast<double>(c.trials)
                  : NAN;
}

// Fig. 15: the mean time of each segment at its middle minute.
Figure TimeFigure(const std::vector<DataRow>& rows, double duration_min) {
  Figure f;
  f.Data("d", rows)
      .Title("Fig. 15: mean assembly time per segment")
      .XLabel("minute of work")
      .YLabel("time (s)")
      .Set("grid")
      .Set(fmt::format("xrange [0:{:g}]", duration_min))
      .Draw({"$d", "1:2:3:4", "with yerrorlines pt 7", "virtual"});
  return f;
}

// Fig. 16: each segment's success rate, with the paper's first and last.
Figure RateFigure(const std::vector<DataRow>& rows, double duration_min, std::size_t ns) {
  const double n = static_cast<double>(ns);
  Figure f;
  f.Data("d", rows)
      .Data("p", {DataRow().Short(0.5 * duration_min / n).Number(0.96),
                  DataRow().Short(duration_min * (1 - 0.5 / n)).Number(0.75)})
      .Title("Fig. 16: assembly success rate per segment")
      .XLabel("minute of work")
      .YLabel("success rate")
      .Set("yrange [0:1.05]")
      .Set("grid")
      .Set("key left bottom")
      .Set(fmt::format("xrange [0:{:g}]", duration_min))
      .Draw({"$d", "1:2:3:4", "with yerrorlines pt 7", "virtual (Wilson 95 %)"})
      .Draw({"$p", "1:2", "with points pt 5 ps 1.5", "paper, virtual (first, last)"});
  return f;
}

// What the section shows and how: the work rate, Eq. 6, the intervals.
std::string FatigueIntro(const experiment::ExperimentRun& run) {
  return fmt::format(
      "## Fatigue over one hour (Sec. 5.4, Figs. 15-16)\n\n"
      "Work rate from {} pilot cycles at A = 0: {:.4g} J per second of assembly. Each "
      "segment's cycles start with the work back-to-back cycles would have done by "
      "their minute; Psi_c = (A_max - A) / A_max with A_max = {:.4g} J (Eq. 6). "
      "Success rate with its 95 % Wilson interval, over the cycles that ended without "
      "a numerical failure (those say nothing about the assembly: see Numerical "
      "health); mean time of completed cycles with its 95 % t interval.\n\n",
      run.pilot.records.size(), run.work_rate, run.file->scene.params.fatigue.a_max);
}

// The segments' table, Markdown and figures.
void DescribeSegments(const experiment::ExperimentRun& run, const SegmentOutcomes& o,
                      Section* out) {
  const experiment::DesignRun& d = run.run;
  const double a_max = run.file->scene.params.fatigue.a_max;
  Table table({"segment", "minute_start", "minute_end", "work_start_J", "work_end_J",
               "psi_start", "psi_end", "cycles", "completed", "numerical_failures",
               "success_rate", "wilson_lower", "wilson_upper", "mean_time_s",
               "ci_lower_s", "ci_upper_s"});
  MarkdownTable md{{"segment", "A at start (J)", "Psi_c at start", "Psi_c at end",
                    "success rate", "mean time (s)"}};
  std::vector<DataRow> fig15, fig16;
  for (std::size_t s = 0; s < d.conditions.size(); ++s) {
    const experiment::Condition& c = d.conditions[s];
    const stats::Count& n = o.counts[s];
    const stats::Interval w = stats::WilsonInterval(n);
    const stats::Summary t = stats::Summarize(o.times[s]);
    const double rate = SuccessRate(n);
    const double psi0 = human::FatigueCoefficient(c.work_start, a_max);
    const double psi1 = human::FatigueCoefficient(c.work_end, a_max);
    table.AddRow({c.name, c.minute_start, c.minute_end, c.work_start, c.work_end, psi0,
                  psi1, n.trials, n.successes, o.numerical[s], rate, w.lower, w.upper,
                  t.mean.value_or(NAN), t.ci ? t.ci->lower : NAN,
                  t.ci ? t.ci->upper : NAN});
    md.AddRow({c.name, fmt::format("{:.4g}", c.work_start), fmt::format("{:.5f}", psi0),
               fmt::format("{:.5f}", psi1),
               fmt::format("{}/{} = {:.2f} [{:.2f}, {:.2f}]", n.successes, n.trials, rate,
                           w.lower, w.upper),
               MeanCi(t)});
    const double mid = 0.5 * (c.minute_start + c.minute_end);
    if (t.mean) fig15.push_back(DataRow().Number(mid).MeanAndInterval(t));
    fig16.push_back(DataRow().Number(mid).Number(rate).Number(w.lower).Number(w.upper));
  }
  out->tables.emplace_back("fatigue_segments.csv", std::move(table));
  out->markdown = FatigueIntro(run) + ToMarkdown(md);
  const double duration =
      run.file->Input<experiment::FatigueInput>().fatigue.duration_min;
  out->plots.push_back({"plots/fatigue_time.png",
                        "Fig. 15: mean assembly time in each segment",
                        GnuplotScript(TimeFigure(fig15, duration))});
  out->plots.push_back({"plots/fatigue_success.png",
                        "Fig. 16: assembly success rate in each segment",
                        GnuplotScript(RateFigure(fig16, duration, d.conditions.size()))});
}

// The first and the last segment's cycles paired by their streams (segment
// s's cycle j runs on the streams of every segment's cycle j): the times of
// those both completed, and how the outcome changed across the pairs.
struct FirstLastPairs {
  std::vector<double> last_times, first_times;
  std::int64_t fell = 0, rose = 0, pairs = 0;
};

FirstLastPairs PairFirstAndLast(const experiment::DesignRun& d) {
  const std::size_t last = d.conditions.size() - 1;
  std::map<std::uint64_t, const experiment::CycleResult*> first_by_cycle;
  for (const experiment::CycleRecord& r : d.records)
    if (r.condition == 0 && !r.result.numerical_failure)
      first_by_cycle[r.cycle] = &r.result;
  FirstLastPairs out;
  for (const experiment::CycleRecord& r : d.records) {
    if (r.condition != last || r.result.numerical_failure) continue;
    const auto it = first_by_cycle.find(r.cycle);
    if (it == first_by_cycle.end()) continue;
    const experiment::CycleResult& before = *it->second;
    ++out.pairs;
    out.fell += before.completed && !r.result.completed;
    out.rose += !before.completed && r.result.completed;
    if (before.completed && r.result.completed) {
      out.last_times.push_back(r.result.time);
      out.first_times.push_back(before.time);
    }
  }
  return out;
}

constexpr const char* kTimeClaim =
    "mean assembly time rises from the first to the last segment";
constexpr const char* kTimeTest =
    "paired t test over the cycles completed in both segments, one-sided (last > first), "
    "5 %";
constexpr const char* kRateClaim =
    "the assembly success rate falls from the first to the last segment (paper: 0.96 to "
    "0.75)";
constexpr const char* kRateTest =
    "McNemar's exact test over the cycles paired across the segments, one-sided (rate "
    "fell), 5 %";

nlohmann::json TimeClaim(const FirstLastPairs& pairs, nlohmann::json* tests) {
  std::string why;
  const auto w = PairedIfDefined(pairs.last_times, pairs.first_times,
                                 "cycles completed in both segments", &why);
  if (!w) return UntestableClaim(kTimeClaim, kTimeTest, why);
  (*tests)["time_last_minus_first"] = {{"pairs", w->n},
                                       {"mean_difference_s", w->mean_difference},
                                       {"ci_lower_s", w->ci.lower},
                                       {"ci_upper_s", w->ci.upper},
                                       {"p_greater", w->p_greater}};
  return Claim(
      kTimeClaim, w->mean_difference > 0 && w->p_greater < 0.05, kTimeTest,
      fmt::format("last - first = {:.4f} s over {} paired cycles, 95 % CI "
                  "[{:.4f}, {:.4f}], p = {:.4f}",
                  w->mean_difference, w->n, w->ci.lower, w->ci.upper, w->p_greater));
}

nlohmann::json RateClaim(const stats::Count& first, const stats::Count& last,
                         const FirstLastPairs& pairs, double psi_end,
                         nlohmann::json* tests) {
  const double p = stats::McNemarRateFellP(pairs.fell, pairs.rose);
  (*tests)["success_first"] = {{"successes", first.successes}, {"cycles", first.trials}};
  (*tests)["success_last"] = {{"successes", last.successes}, {"cycles", last.trials}};
  (*tests)["paired_cycles"] = pairs.pairs;
  (*tests)["pairs_succeeded_then_failed"] = pairs.fell;
  (*tests)["pairs_failed_then_succeeded"] = pairs.rose;
  (*tests)["p_rate_fell"] = p;
  return Claim(
      kRateClaim, p < 0.05, kRateTest,
      fmt::format("{}/{} then {}/{}; of {} paired cycles {} succeeded then failed "
                  "and {} failed then succeeded, p = {:.4f}; Psi_c at the end of "
                  "the hour {:.5f}",
                  first.successes, first.trials, last.successes, last.trials, pairs.pairs,
                  pairs.fell, pairs.rose, p, psi_end));
}

}  // namespace

Section FatigueSection(const experiment::ExperimentRun& run) {
  const experiment::DesignRun& d = run.run;
  const double a_max = run.file->scene.params.fatigue.a_max;
  const std::size_t ns = d.conditions.size();
  const double psi_end =
      ns ? human::FatigueCoefficient(d.conditions[ns - 1].work_end, a_max) : 1.0;
  const SegmentOutcomes outcomes = CountSegments(d);
  Section out;
  out.tables.emplace_back("fatigue_cycles.csv", CyclesTable(d));
  out.tables.emplace_back("fatigue_pilot_cycles.csv", CyclesTable(run.pilot));
  DescribeSegments(run, outcomes, &out);

  nlohmann::json claims = nlohmann::json::array();
  nlohmann::json tests = nlohmann::json::object();
  if (ns < 2) {
    const std::string why =
        fmt::format("the run has {} segment(s): a trend needs two", ns);
    claims.push_back(UntestableClaim(kTimeClaim, kTimeTest, why));
    claims.push_back(UntestableClaim(kRateClaim, kRateTest, why));
  } else {
    const FirstLastPairs pairs = PairFirstAndLast(d);
    claims.push_back(TimeClaim(pairs, &tests));
    claims.push_back(
        RateClaim(outcomes.counts[0], outcomes.counts[ns - 1], pairs, psi_end, &tests));
  }
  out.summary = {{"work_rate_J_per_s", run.work_rate},
                 {"a_max_J", a_max},
                 {"psi_end_of_hour", psi_end},
                 {"tests", tests},
                 {"claims", claims}};
  return out;
}

}  // namespace vahf::report
