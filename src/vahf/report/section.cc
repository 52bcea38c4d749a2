#include "vahf/report/section.h"

#include <fmt/format.h>

#include "vahf/core/error.h"
#include "vahf/report/cost.h"
#include "vahf/report/health.h"

namespace vahf::report {

nlohmann::json Claim(const std::string& claim, bool reproduced, const std::string& test,
                     const std::string& evidence) {
  return {{"claim", claim},
          {"verdict", reproduced ? "yes" : "no"},
          {"reproduced", reproduced},
          {"test", test},
          {"evidence", evidence}};
}

nlohmann::json UntestableClaim(const std::string& claim, const std::string& test,
                               const std::string& why) {
  return {{"claim", claim},
          {"verdict", "untestable"},
          {"reproduced", false},
          {"test", test},
          {"evidence", why}};
}

std::optional<stats::WelchResult> WelchIfDefined(const std::vector<double>& a,
                                                 const std::vector<double>& b,
                                                 const std::string& a_name,
                                                 const std::string& b_name,
                                                 std::string* why) {
  if (a.size() < 2 || b.size() < 2) {
    *why = fmt::format("{} has {} value(s) and {} {}: the test needs two each", a_name,
                       a.size(), b_name, b.size());
    return std::nullopt;
  }
  if (stats::SampleStandardDeviation(a) == 0 && stats::SampleStandardDeviation(b) == 0) {
    *why = fmt::format(
        "neither {} ({:.6g} every time) nor {} ({:.6g} every time) varies: "
        "the t statistic is undefined",
        a_name, a.front(), b_name, b.front());
    return std::nullopt;
  }
  return stats::WelchTTest(a, b);
}

std::optional<stats::PairedTResult> PairedIfDefined(const std::vector<double>& a,
                                                    const std::vector<double>& b,
                                                    const std::string& pairs,
                                                    std::string* why) {
  if (a.size() < 2) {
    *why = fmt::format("{} pair(s) of {}: the test needs two", a.size(), pairs);
    return std::nullopt;
  }
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  if (stats::SampleStandardDeviation(d) == 0) {
    *why =
        fmt::format("the {} {} differ by {:.6g} every time: the t statistic is undefined",
                    a.size(), pairs, d.front());
    return std::nullopt;
  }
  return stats::PairedTTest(a, b);
}

std::string MeanCi(const stats::Summary& s) {
  if (!s.mean) return "-";
  if (!s.ci) return fmt::format("{:.3f}", *s.mean);
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]", *s.mean, s.ci->lower, s.ci->upper);
}

Table CyclesTable(const experiment::DesignRun& run) {
  Table t({"condition", "group", "cycle", "start_minute", "initial_work_J", "repetition",
           "position", "part", "status", "part_start_s", "part_time_s", "work_end_J",
           "cycle_completed", "cycle_time_s"});
  for (const experiment::CycleRecord& r : run.records) {
    const experiment::Condition& c = run.conditions[r.condition];
    for (std::size_t p = 0; p < r.result.parts.size(); ++p) {
      const experiment::PartRun& part = r.result.parts[p];
      t.AddRow({c.name, c.group, static_cast<std::int64_t>(r.cycle), r.start_minute,
                r.initial_work, std::int64_t{r.repetition}, static_cast<std::int64_t>(p),
                part.trial.part, std::string(sim::StatusName(part.trial.status)),
                part.start_time, part.trial.end_time, part.trial.work,
                std::int64_t{r.result.completed ? 1 : 0}, r.result.time});
    }
  }
  return t;
}

Section SectionFor(const std::string& kind, const experiment::ExperimentRun& run,
                   Section analysis) {
  Section out = std::move(analysis);
  out.kind = kind;
  out.summary["health"] = HealthJson(run.run);
  out.markdown += HealthMarkdown(run.run);
  // A kind that measures its own cost (precision: per setting, whose trials
  // one pooled table would mix) has filled `measured` already.
  if (out.measured.is_null()) {
    Table cost = CostTable(run.run);
    out.markdown += CostMarkdown(cost);
    out.measured = {{"cost", CostJson(cost)}};
    out.measured_tables.emplace_back(kind + "_cost.csv", std::move(cost));
  }
  return out;
}

}  // namespace vahf::report
