// Numerical health of a design, on hand-made records: per condition the
// cycles, the numerical failures, the warnings summed over every part trial
// and the deepest contact against the smallest bound, in JSON and Markdown.
#include "vahf/report/health.h"

#include <gtest/gtest.h>

namespace vahf::report {
namespace {

experiment::CycleRecord Cycle(std::size_t condition, double depth, bool failed,
                              std::int64_t bound_warnings) {
  experiment::CycleRecord r;
  r.condition = condition;
  experiment::PartRun part;
  part.trial.max_penetration = depth;
  part.trial.penetration_bound = 3.4e-6;
  part.trial.warnings.Note(WarningKind::kPenetrationBound, 0.25, "depth", bound_warnings);
  r.result.warnings.Add(part.trial.warnings);
  r.result.parts.push_back(part);
  r.result.numerical_failure = failed;
  return r;
}

TEST(Health, SumsPerCondition) {
  experiment::DesignRun run;
  run.conditions.resize(2);
  run.conditions[0].name = "general";
  run.conditions[1].name = "worst";
  run.records = {Cycle(0, 2e-6, false, 0), Cycle(0, 5e-6, true, 3), Cycle(1, 1e-6, false, 0)};
  const nlohmann::json h = HealthJson(run);
  ASSERT_EQ(h.at("conditions").size(), 2u);
  const nlohmann::json& g = h.at("conditions")[0];
  EXPECT_EQ(g.at("condition"), "general");
  EXPECT_EQ(g.at("cycles"), 2);
  EXPECT_EQ(g.at("numerical_failures"), 1);
  EXPECT_DOUBLE_EQ(g.at("max_penetration_m").get<double>(), 5e-6);
  EXPECT_DOUBLE_EQ(g.at("penetration_bound_m").get<double>(), 3.4e-6);
  EXPECT_EQ(g.at("warnings").at("penetration_bound").at("count"), 3);
  EXPECT_TRUE(h.at("conditions")[1].at("warnings").empty());
  EXPECT_EQ(h.at("warnings"), 3);
  const std::string md = HealthMarkdown(run);
  EXPECT_NE(md.find("| general | 2 | 1 | 5 | 3.4 | penetration_bound 3 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| worst | 1 | 0 | 1 | 3.4 | none |"), std::string::npos) << md;
}

}  // namespace
}  // namespace vahf::report
