// The handbooks section of a paper run (report/handbook_section.h), on a
// paper-like run built by hand: the shipped cylinder scene and part trials
// whose contact and completion instants the test sets, so the expected
// classes and times follow from the inputs, not from a run.
#include "vahf/report/handbook_section.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "vahf/data/handbook_classification.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string Source(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

// The part trial at `position` of a cycle: completed at `done` s after
// touching at `touch` s (-1: never touched).
experiment::PartRun Completed(const scene::Scene& s, std::size_t position, double touch,
                              double done) {
  experiment::PartRun p;
  p.trial.status = sim::Status::kCompleted;
  p.trial.part = s.parts[static_cast<std::size_t>(s.sequence[position])].name;
  p.trial.first_contact_time = touch;
  p.trial.completion_time = done;
  p.trial.end_time = done;
  return p;
}

class HandbookSectionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    paper_.kind = "paper";
    paper_.name = "paper";
    at_.kind = "assembly_time";
    at_.name = "assembly_time";
    at_.scene_path = Source("experiments/scenes/hydraulic_cylinder.json");
    at_.scene = scene::LoadScene(at_.scene_path);
    bd_ =
        data::ReadBdInsertion(Source("data/handbooks/boothroyd_dewhurst_insertion.csv"));
    mtm_ = data::ReadMtmPosition(Source("data/handbooks/mtm1_position.csv"));
    run_.file = &paper_;
    experiment::ExperimentRun part;
    part.file = &at_;
    part.run.conditions.push_back({"male P50", "male", nullptr});
    const scene::Scene& s = at_.scene;
    // Two cycles: every part touches and completes, but the seal ring of the
    // second completes without touching.
    for (std::uint64_t j = 0; j < 2; ++j) {
      experiment::CycleRecord r;
      r.cycle = j;
      for (std::size_t p = 0; p < s.sequence.size(); ++p) {
        const double pd = static_cast<double>(p), jd = static_cast<double>(j);
        const double touch = (j == 1 && p == 2) ? -1 : 1.0 + pd + 0.25 * jd;
        r.result.parts.push_back(Completed(s, p, touch, 3.0 + 2 * pd + 0.5 * jd));
      }
      r.result.completed = true;
      part.run.records.push_back(r);
    }
    run_.parts.push_back(std::move(part));
  }

  scene::ExperimentFile paper_, at_;
  experiment::ExperimentRun run_;
  data::BdInsertionTable bd_;
  data::MtmPositionTable mtm_;
};

TEST_F(HandbookSectionTest, EachPartHasItsClassesTimesAndTheSources) {
  const Section s = HandbookSection(&run_.parts[0], bd_, mtm_);
  EXPECT_EQ(s.kind, "handbooks");
  EXPECT_TRUE(s.summary.at("claims").empty());
  for (const char* id : {"**S1**", "**S2**", "**S3**"})
    EXPECT_THAT(s.markdown, HasSubstr(id));
  const scene::Scene& scene = at_.scene;
  ASSERT_EQ(s.summary.at("parts").size(), scene.sequence.size());
  for (std::size_t p = 0; p < scene.sequence.size(); ++p) {
    std::string why;
    const auto fit = data::InsertionFitOf(scene, p, &why);
    ASSERT_TRUE(fit.has_value()) << why;
    const data::HandbookClasses c = data::ClassifyInsertion(*fit, mtm_, bd_);
    const nlohmann::json& row = s.summary.at("parts").at(p);
    EXPECT_EQ(row.at("boothroyd_dewhurst").at("code"), c.bd.code);
    EXPECT_EQ(row.at("mtm1").at("code"), c.mtm.code);
    EXPECT_THAT(s.markdown, HasSubstr(c.bd.why));
    EXPECT_THAT(s.markdown, HasSubstr(c.mtm.why));
    ASSERT_TRUE(c.bd.seconds.has_value());
    EXPECT_THAT(s.markdown, HasSubstr(fmt::format("{:.2f} ({})", *c.bd.seconds,
                                                  bd_.Find(c.bd.code)->source)));
    // The insertion: completion minus first contact, of the trials that touched.
    std::vector<double> insertion;
    for (const auto& r : run_.parts[0].run.records) {
      const sim::TrialResult& t = r.result.parts[p].trial;
      if (t.first_contact_time >= 0)
        insertion.push_back(t.completion_time - t.first_contact_time);
    }
    const stats::Summary sum = stats::Summarize(insertion);
    EXPECT_EQ(row.at("insertion_n"), sum.n);
    EXPECT_DOUBLE_EQ(row.at("insertion_mean_s").get<double>(), *sum.mean);
    EXPECT_EQ(row.at("completed_without_contact"), 2 - sum.n);
  }
  EXPECT_THAT(s.markdown, HasSubstr("never touched a fixed part"));
}

TEST_F(HandbookSectionTest, AnEmptyMtmTableShowsNoTimeAndSaysWhy) {
  ASSERT_TRUE(mtm_.rows.empty());  // as shipped
  const Section s = HandbookSection(&run_.parts[0], bd_, mtm_);
  EXPECT_THAT(s.markdown, HasSubstr("No MTM-1 time is shown"));
  EXPECT_THAT(s.markdown, HasSubstr("Unverified"));
}

TEST_F(HandbookSectionTest, AnMtmRowShowsItsTimeAndSource) {
  std::string why;
  const auto fit = data::InsertionFitOf(at_.scene, 0, &why);
  ASSERT_TRUE(fit.has_value());
  const std::string code = data::ClassifyInsertion(*fit, mtm_, bd_).mtm.code;
  const data::MtmPositionTable mtm = data::ParseMtmPosition(
      "code,fit_class,symmetry,handling,tmu,source\n" + code + "," + code.substr(1, 1) +
          "," + code.substr(2, code.size() - 3) + ",easy,10,T1\n",
      "test.csv");
  const Section s = HandbookSection(&run_.parts[0], bd_, mtm);
  EXPECT_THAT(s.markdown,
              HasSubstr(fmt::format("{:.2f} (T1)", 10 * data::kSecondsPerTmu)));
  EXPECT_THAT(s.markdown, Not(HasSubstr("No MTM-1 time is shown")));
}

TEST_F(HandbookSectionTest, WithoutAnAssemblyTimeExperimentItSaysSo) {
  const Section s = HandbookSection(nullptr, bd_, mtm_);
  EXPECT_THAT(s.markdown, HasSubstr("no experiment that times the parts"));
  EXPECT_THAT(s.markdown, HasSubstr("**S2**"));
}

}  // namespace
}  // namespace vahf::report
