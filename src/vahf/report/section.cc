#include "vahf/report/section.h"

#include <fmt/format.h>

#include "vahf/core/error.h"
#include "vahf/report/cost.h"
#include "vahf/report/health.h"

namespace vahf::report {

nlohmann::json Claim(const std::string& claim, bool reproduced, const std::string& test,
                     const std::string& evidence) {
  return {{"claim", claim}, {"reproduced", reproduced}, {"test", test},
          {"evidence", evidence}};
}

std::string MeanCi(const stats::Summary& s) {
  if (!s.mean) return "-";
  if (!s.ci) return fmt::format("{:.3f}", *s.mean);
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]", *s.mean, s.ci->lower, s.ci->upper);
}

Table CyclesTable(const experiment::DesignRun& run) {
  Table t({"condition", "group", "cycle", "start_minute", "initial_work_J", "position",
           "part", "status", "part_start_s", "part_time_s", "work_end_J",
           "cycle_completed", "cycle_time_s"});
  for (const experiment::CycleRecord& r : run.records) {
    const experiment::Condition& c = run.conditions[r.condition];
    for (std::size_t p = 0; p < r.result.parts.size(); ++p) {
      const experiment::PartRun& part = r.result.parts[p];
      t.AddRow({c.name, c.group, static_cast<std::int64_t>(r.cycle), r.start_minute,
                r.initial_work, static_cast<std::int64_t>(p), part.trial.part,
                std::string(sim::StatusName(part.trial.status)), part.start_time,
                part.trial.end_time, part.trial.work,
                std::int64_t{r.result.completed ? 1 : 0}, r.result.time});
    }
  }
  return t;
}

namespace {

// The analysis of the run's kind.
Section KindSection(const experiment::ExperimentRun& run) {
  const std::string& kind = run.file->kind;
  if (kind == "table1") return Table1Section(run);
  if (kind == "assembly_time") return AssemblyTimeSection(run);
  if (kind == "human_factors_groups") return HumanFactorsGroupsSection(run);
  if (kind == "fatigue") return FatigueSection(run);
  if (kind == "precision") return PrecisionSection(run);
  VAHF_CHECK(false, "no section for this kind");
  return {};
}

}  // namespace

Section SectionFor(const experiment::ExperimentRun& run) {
  Section out = KindSection(run);
  out.summary["health"] = HealthJson(run.run);
  out.markdown += HealthMarkdown(run.run);
  // A kind that measures its own cost (precision: per setting, whose trials
  // one pooled table would mix) has filled `measured` already.
  if (out.measured.is_null()) {
    Table cost = CostTable(run.run);
    out.markdown += CostMarkdown(cost);
    out.measured = {{"cost", CostJson(cost)}};
    out.measured_tables.emplace_back(run.file->kind + "_cost.csv", std::move(cost));
  }
  return out;
}

}  // namespace vahf::report
