// What an experiment's trials cost, on hand-made records: one row per part in
// the order the parts first appear, CPU quantiles (GSL's interpolated ones),
// the total, the mean simulated time and the median real-time factor; the
// same figures in JSON and Markdown.
#include "vahf/report/cost.h"

#include <gtest/gtest.h>

namespace vahf::report {
namespace {

experiment::PartRun Part(const std::string& name, double cpu, double simulated) {
  experiment::PartRun p;
  p.trial.part = name;
  p.trial.cpu_seconds = cpu;
  p.trial.end_time = simulated;
  return p;
}

TEST(Cost, PerPartInOrderOfAppearance) {
  experiment::DesignRun run;
  run.conditions.resize(1);
  for (int k = 0; k < 3; ++k) {
    experiment::CycleRecord r;
    r.result.parts = {Part("rod", 0.1 * (k + 1), 0.6), Part("ring", 0.05, 0.5)};
    run.records.push_back(r);
  }
  const Table t = CostTable(run);
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(std::get<std::string>(t.at(0, 0)), "rod");
  EXPECT_EQ(std::get<std::int64_t>(t.at(0, 1)), 3);
  EXPECT_DOUBLE_EQ(std::get<double>(t.at(0, 2)), 0.2);    // median of 0.1, 0.2, 0.3
  EXPECT_DOUBLE_EQ(std::get<double>(t.at(0, 3)), 0.298);  // 0.2 + 0.98 * 0.1
  EXPECT_DOUBLE_EQ(std::get<double>(t.at(0, 4)), 0.3);
  EXPECT_NEAR(std::get<double>(t.at(0, 5)), 0.6, 1e-15);
  EXPECT_DOUBLE_EQ(std::get<double>(t.at(0, 6)), 0.6);
  EXPECT_DOUBLE_EQ(std::get<double>(t.at(0, 7)), 3.0);  // 0.6 / 0.2
  EXPECT_EQ(std::get<std::string>(t.at(1, 0)), "ring");
  EXPECT_DOUBLE_EQ(std::get<double>(t.at(1, 7)), 10.0);

  const nlohmann::json j = CostJson(t);
  ASSERT_EQ(j.at("parts").size(), 2u);
  EXPECT_EQ(j.at("parts")[0].at("part"), "rod");
  EXPECT_DOUBLE_EQ(j.at("parts")[0].at("cpu_max_s").get<double>(), 0.3);

  const std::string md = CostMarkdown(t);
  EXPECT_NE(md.find("| rod | 3 | 0.200 | 0.298 | 0.300 | 0.6 | 0.600 | 3.00 |"),
            std::string::npos)
      << md;
}

TEST(Cost, AnEmptyRunHasNoRows) {
  experiment::DesignRun run;
  EXPECT_EQ(CostTable(run).rows(), 0u);
}

}  // namespace
}  // namespace vahf::report
