// The synthetic lab's optional working conditions and hour of work
// (synthetic_lab.h; docs/calibration.md, "Synthetic data"): rows carry their
// condition, segments.csv holds each condition's hour at the stated values,
// the dataset loads as a lab dataset, and a bad value is one InputError
// naming file, key, value and rule.
#include "vahf/calibrate/synthetic_lab.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "vahf/core/error.h"
#include "vahf/data/lab_dataset.h"

namespace vahf::calibrate {
namespace {

namespace fs = std::filesystem;

std::string Path(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

experiment::RunnerOptions Quiet(int threads = 2) {
  experiment::RunnerOptions o;
  o.threads = threads;
  o.progress = false;
  return o;
}

// A generator file beside the shipped one's scene, with `extra` keys.
std::string Generator(const std::string& name, const std::string& extra) {
  const fs::path dir = fs::path(::testing::TempDir()) / "synthetic_lab_test";
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".json");
  std::ofstream(file)
      << R"({"format": "vahf-synthetic/1", "name": ")" << name << R"(", "scene": ")"
      << Path("experiments/scenes/steel_block_move.json")
      << R"(", "parameters": {"guidance/kappa": 300, "fatigue/a_max": 25000},
  "operators": [{"name": "a", "sex": "female", "height": 1.6, "arm_length": 0.68},
                {"name": "b", "sex": "male", "height": 1.75, "arm_length": 0.76}],
  "repetitions": 2, "seed": 11)"
      << extra << "}";
  return file.string();
}

TEST(SyntheticLab, ConditionsAndAnHourOfWorkMakeRowsAndSegments) {
  const std::string path = Generator("hour", R"(, "conditions": [{"name": "good"},
      {"name": "poor", "parameters": {"guidance/vision_sigma_depth": 0.01}}],
      "fatigue": {"duration_min": 60, "segments": 4, "pilot_cycles": 2, "trials": 4})");
  const SyntheticLabSpec spec = LoadSyntheticLabSpec(path);
  ASSERT_EQ(spec.conditions.size(), 2u);
  EXPECT_EQ(spec.conditions[1].scene.params.guidance.kappa, 300.0);  // the truth holds
  EXPECT_EQ(spec.conditions[1].scene.params.guidance.vision_sigma_depth, 0.01);
  EXPECT_EQ(spec.fatigue.trials, 4);
  const data::LabDataset lab = GenerateSyntheticLab(spec, Quiet());
  // conditions x operators x repetitions, each a trial of the block.
  ASSERT_EQ(lab.trials.size(), 8u);
  EXPECT_EQ(lab.trials[0].condition, "good");
  EXPECT_EQ(lab.trials[4].condition, "poor");
  EXPECT_EQ(lab.trials[4].operator_id, "a");
  // Each condition's hour: four segments of four cycles; at A_max = 25 kJ
  // the steel block's operator (about 10.7 J/s of work) tires in the third.
  ASSERT_EQ(lab.segments.size(), 8u);
  for (std::size_t k = 0; k < lab.segments.size(); ++k) {
    const data::LabSegment& s = lab.segments[k];
    EXPECT_EQ(s.condition, k < 4 ? "good" : "poor");
    EXPECT_EQ(s.segment, static_cast<int>(k % 4) + 1);
    EXPECT_EQ(s.attempts, 4);
  }
  EXPECT_EQ(lab.segments[0].successes, 4);
  EXPECT_EQ(lab.segments[3].successes, 0);
  EXPECT_TRUE(std::isnan(lab.segments[3].mean_time));

  // It is a lab dataset: written and loaded back, the same rows.
  const fs::path out = fs::path(::testing::TempDir()) / "synthetic_lab_test" / "hour_lab";
  fs::remove_all(out);
  data::WriteLabDataset(lab, out.string());
  const data::LabDataset back = data::LoadLabDataset((out / "dataset.json").string());
  EXPECT_EQ(back.trials.size(), lab.trials.size());
  ASSERT_EQ(back.segments.size(), lab.segments.size());
  EXPECT_EQ(back.segments[2].successes, lab.segments[2].successes);

  // The same bits on one thread.
  const data::LabDataset one = GenerateSyntheticLab(spec, Quiet(1));
  for (std::size_t k = 0; k < lab.segments.size(); ++k)
    EXPECT_EQ(one.segments[k].successes, lab.segments[k].successes);
}

TEST(SyntheticLab, WithoutTheNewKeysTheTrialsAreAsBefore) {
  const SyntheticLabSpec plain = LoadSyntheticLabSpec(Generator("plain", ""));
  const SyntheticLabSpec hour = LoadSyntheticLabSpec(
      Generator("plain_hour", R"(, "fatigue": {"segments": 2, "trials": 2})"));
  const data::LabDataset a = GenerateSyntheticLab(plain, Quiet());
  const data::LabDataset b = GenerateSyntheticLab(hour, Quiet());
  EXPECT_TRUE(a.segments.empty());
  EXPECT_TRUE(a.segments_file.empty());
  EXPECT_EQ(b.segments.size(), 2u);
  ASSERT_EQ(a.trials.size(), b.trials.size());
  for (std::size_t k = 0; k < a.trials.size(); ++k) {
    EXPECT_EQ(a.trials[k].condition, "synthetic");
    EXPECT_EQ(a.trials[k].time, b.trials[k].time);
  }
}

struct Bad {
  const char* extra;
  const char* where;
};

TEST(SyntheticLab, EachBadValueIsOneInputErrorNamingItsKey) {
  const Bad cases[] = {
      {R"(, "fatigue": {"segments": 4})", "/fatigue/trials"},  // required
      {R"(, "fatigue": {"trials": 0})", "/fatigue/trials"},
      {R"(, "fatigue": {"trials": 3, "segmnts": 4})", "/fatigue/segmnts"},
      {R"(, "fatigue": {"trials": 3, "duration_min": -1})", "/fatigue/duration_min"},
      {R"(, "condition": "x", "conditions": [{"name": "y"}])", "/conditions"},
      {R"(, "conditions": [])", "/conditions"},
      {R"(, "conditions": [{"name": ""}])", "/conditions/0/name"},
      {R"(, "conditions": [{"name": "y"}, {"name": "y"}])", "/conditions/1/name"},
      {R"(, "conditions": [{"name": "y", "parameters": {"guidance/kappa": -1}}])",
       "/conditions/0/parameters/guidance~1kappa"},
      {R"(, "conditions": [{"name": "y", "scene": "nowhere.json"}])",
       "/conditions/0/scene"},
      // A choice (a learning model) is the generator's, for every condition.
      {R"(, "conditions": [{"name": "y", "parameters": {"learning/model": "de_jong"}}])",
       "/conditions/0/parameters/learning~1model"},
      // The rule D1 < D2 < D3 for operator b (arm 0.76 m, stature 1.75 m:
      // D1 = 0.684 m, D2 = 0.6825 m), which the scene's own operator keeps.
      {R"(, "conditions": [{"name": "y", "parameters": {"reach/d1_arm_fraction": 0.9}}])",
       "/conditions/0/name"},
  };
  for (const Bad& c : cases) {
    const std::string path = Generator("bad", c.extra);
    try {
      LoadSyntheticLabSpec(path);
      ADD_FAILURE() << c.extra << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path) << c.extra;
      EXPECT_EQ(e.where(), c.where) << c.extra << ": " << e.what();
      EXPECT_FALSE(e.rule().empty()) << c.extra;
    }
  }
}

}  // namespace
}  // namespace vahf::calibrate
