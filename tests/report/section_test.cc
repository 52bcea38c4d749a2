// Tests of the shared pieces of the report sections (report/section.h).
#include "vahf/report/section.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>

#include "vahf/kinds/kind.h"

namespace vahf::report {
namespace {

TEST(MeanCi, MeanWithItsIntervalTheMeanAloneOrADash) {
  // 1, 2, 3: mean 2, sd 1, t(0.975, 2) = 4.303: 2 -+ 2.484.
  EXPECT_EQ(MeanCi(stats::Summarize({1.0, 2.0, 3.0})), "2.000 [-0.484, 4.484]");
  EXPECT_EQ(MeanCi(stats::Summarize({1.25})), "1.250");  // one sample: no interval
  EXPECT_EQ(MeanCi(stats::Summarize({})), "-");
}

TEST(Claim, HoldsEveryField) {
  const nlohmann::json c = Claim("eta rises", true, "t test", "0.2 [0.1, 0.3]");
  EXPECT_EQ(c["claim"], "eta rises");
  EXPECT_EQ(c["verdict"], "yes");
  EXPECT_EQ(c["reproduced"], true);
  EXPECT_EQ(c["test"], "t test");
  EXPECT_EQ(c["evidence"], "0.2 [0.1, 0.3]");
  EXPECT_EQ(Claim("eta rises", false, "t test", "-0.1")["verdict"], "no");
}

TEST(Claim, AnUntestableClaimSaysWhyAndIsNotReproduced) {
  const nlohmann::json c = UntestableClaim("eta rises", "t test", "one cycle");
  EXPECT_EQ(c["verdict"], "untestable");
  EXPECT_EQ(c["reproduced"], false);
  EXPECT_EQ(c["evidence"], "one cycle");
}

TEST(WelchIfDefined, SaysWhyWhenTheTestIsUndefined) {
  std::string why;
  EXPECT_FALSE(WelchIfDefined({1.0}, {1.0, 2.0}, "a", "b", &why));
  EXPECT_EQ(why, "a has 1 value(s) and b 2: the test needs two each");
  EXPECT_FALSE(WelchIfDefined({3.0, 3.0}, {4.0, 4.0, 4.0}, "a", "b", &why));
  EXPECT_EQ(why,
            "neither a (3 every time) nor b (4 every time) varies: the t statistic is "
            "undefined");
  const auto w = WelchIfDefined({3.0, 3.0}, {4.0, 5.0}, "a", "b", &why);
  ASSERT_TRUE(w);
  EXPECT_DOUBLE_EQ(w->mean_difference, -1.5);
}

// A fatigue run whose segments each completed every cycle in exactly 10 s
// (as when every cycle ends at the same event): Welch's t is undefined, so the
// time claim is untestable, with its reason, and stays in the table; the rate
// claim is still tested. Before, the section threw after every trial had run.
TEST(FatigueSection, ATrendWithoutSpreadIsUntestableNotAnError) {
  const scene::ExperimentFile file =
      kinds::LoadExperiment(std::string(VAHF_SOURCE_DIR) + "/experiments/fatigue.json");
  experiment::ExperimentRun run;
  run.file = &file;
  const auto scene = std::make_shared<const scene::Scene>(file.scene);
  for (int s = 0; s < 2; ++s) {
    experiment::Condition c;
    c.name = "segment " + std::to_string(s);
    c.scene = scene;
    c.minute_end = 30;
    run.run.conditions.push_back(c);
    for (int j = 0; j < 3; ++j) {
      experiment::CycleRecord r;
      r.condition = static_cast<std::size_t>(s);
      r.cycle = static_cast<std::uint64_t>(j);
      r.result.completed = true;
      r.result.time = 10.0;
      run.run.records.push_back(r);
    }
  }
  const Section section = FatigueSection(run);
  const nlohmann::json& claims = section.summary.at("claims");
  ASSERT_EQ(claims.size(), 2u);
  EXPECT_EQ(claims[0].at("verdict"), "untestable") << claims[0].dump();
  EXPECT_THAT(claims[0].at("evidence").get<std::string>(),
              ::testing::HasSubstr("differ by 0 every time"));
  EXPECT_EQ(claims[1].at("verdict"), "no") << claims[1].dump();  // 3/3 then 3/3
}

}  // namespace
}  // namespace vahf::report
