// Recovery of stated parameter values from synthetic lab datasets: the model
// at kappa_true plays the lab (synthetic_lab.h), Ceres fits kappa back
// (calibration.h), and the fit's 95 % interval must hold kappa_true; over
// many datasets (other lab draws, other virtual keys) about 95 % of them
// must. This tests the chain end to end: lab trials, targets and their
// variances, the whitened residuals, Ceres' covariance.
#include "vahf/calibrate/calibration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "vahf/calibrate/synthetic_lab.h"
#include "vahf/core/error.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {
namespace {

std::string Path(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

constexpr double kKappaTrue = 250.0;  // N/m; the scene default is 400

SyntheticLabSpec BlockLab(std::uint64_t seed) {
  SyntheticLabSpec spec;
  spec.file = "test";
  spec.name = "steel_block_synthetic";
  spec.scene = scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  spec.scene.params.guidance.kappa = kKappaTrue;
  spec.truth = {{"guidance/kappa", kKappaTrue}};
  spec.operators = {{"female 1", "female", 1.62, 0.70, ""},
                    {"male 1", "male", 1.78, 0.77, ""}};
  spec.repetitions = 12;
  spec.seed = seed;
  spec.time_sd = 0.02;
  spec.time_resolution = 0.001;
  return spec;
}

CalibrationSpec KappaFromTime() {
  CalibrationSpec spec;
  spec.stages.emplace_back();
  spec.stages[0].parameters = {{"guidance/kappa", 400.0, 50.0, 2000.0, "/parameters/0"}};
  spec.stages[0].targets = {{"assembly_time", "block", false, "/targets/0", 0, 0, ""}};
  return spec;
}

// A calibration of one stage.
CalibrationResult Fit(const scene::Scene& scene, const data::LabDataset& lab,
                      const CalibrationSpec& spec, const std::string& file,
                      std::uint64_t seed, int trials,
                      const experiment::RunnerOptions& options,
                      const CalibrationProgress& progress = {}) {
  const std::vector<CalibrationResult> stages =
      Calibrate(scene, lab, spec, file, seed, trials, options, progress);
  EXPECT_EQ(stages.size(), 1u);
  return stages.at(0);
}

experiment::RunnerOptions Quiet() {
  experiment::RunnerOptions o;
  o.threads = 2;
  o.progress = false;
  return o;
}

TEST(Calibration, RecoversKappaFromASyntheticLabWithinItsInterval) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(BlockLab(101), Quiet());
  ASSERT_EQ(lab.trials.size(), 24u);
  const CalibrationResult r = Fit(scene, lab, KappaFromTime(), "test", 7, 24, Quiet(),
                                  [](const std::string& l) { std::puts(l.c_str()); });
  ASSERT_TRUE(r.covariance_ok) << r.ceres_full;
  const FittedParameter& k = r.parameters[0];
  EXPECT_GT(k.standard_error, 0.0);
  EXPECT_LE(k.ci.lower, kKappaTrue) << r.ceres_brief;
  EXPECT_GE(k.ci.upper, kKappaTrue) << r.ceres_brief;
  // The fit moved: the start, 400 N/m, lies outside the interval.
  EXPECT_LT(k.ci.upper, 400.0) << r.ceres_brief;
  // One target, one parameter: the fit matches the lab's mean time.
  EXPECT_LT(std::abs(r.targets[0].residual), 0.1);
  EXPECT_FALSE(k.has_profile);  // Levenberg-Marquardt: Ceres' interval only
}

// The golden_section solver's stage also gives the profile interval
// (ProfileBounds on the stage's own cost): on the same lab it holds the
// estimate and kappa_true, closes on both sides well inside the bounds, and
// leaves out the start, 400 N/m.
TEST(Calibration, GoldenSectionStageGivesAProfileIntervalHoldingTheTruth) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(BlockLab(101), Quiet());
  CalibrationSpec spec = KappaFromTime();
  spec.stages[0].solver = "golden_section";
  spec.tolerance = 0.01;
  spec.max_iterations = 30;
  const CalibrationResult r = Fit(scene, lab, spec, "test", 7, 24, Quiet());
  const FittedParameter& k = r.parameters[0];
  ASSERT_TRUE(k.has_profile) << r.search_log;
  EXPECT_FALSE(k.profile_open_lower) << r.search_log;
  EXPECT_FALSE(k.profile_open_upper) << r.search_log;
  EXPECT_LE(k.profile.lower, k.estimate);
  EXPECT_GE(k.profile.upper, k.estimate);
  EXPECT_LE(k.profile.lower, kKappaTrue) << r.search_log;
  EXPECT_GE(k.profile.upper, kKappaTrue) << r.search_log;
  EXPECT_GT(k.profile.lower, 50.0);
  EXPECT_LT(k.profile.upper, 400.0) << r.search_log;
  EXPECT_NE(r.search_log.find("profile: cost"), std::string::npos);
}

TEST(Calibration, SameInputsGiveTheSameBitsOnAnyThreadCount) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(BlockLab(5), Quiet());
  experiment::RunnerOptions one = Quiet();
  one.threads = 1;
  const data::LabDataset lab1 = GenerateSyntheticLab(BlockLab(5), one);
  ASSERT_EQ(lab.trials.size(), lab1.trials.size());
  for (std::size_t i = 0; i < lab.trials.size(); ++i)
    EXPECT_EQ(std::isnan(lab.trials[i].time) ? 0.0 : lab.trials[i].time,
              std::isnan(lab1.trials[i].time) ? 0.0 : lab1.trials[i].time);
  const CalibrationResult a = Fit(scene, lab, KappaFromTime(), "test", 3, 12, Quiet());
  const CalibrationResult b = Fit(scene, lab, KappaFromTime(), "test", 3, 12, one);
  EXPECT_EQ(a.parameters[0].estimate, b.parameters[0].estimate);
  EXPECT_EQ(a.parameters[0].standard_error, b.parameters[0].standard_error);
}

// Coverage: over kDatasets generated datasets, each calibrated with its own
// virtual keys, the share of 95 % intervals that hold kappa_true. With the
// intervals right it is Binomial(20, 0.95): 17 or more with probability
// 0.98. The figure is printed for the record (docs/calibration.md).
TEST(Calibration, NinetyFivePercentIntervalsCoverTheTruthAsOftenAsTheyClaim) {
  // VAHF_COVERAGE_DATASETS=N runs N datasets instead (a long soak; the
  // assertion then scales: at least 85 % covered).
  const char* env = std::getenv("VAHF_COVERAGE_DATASETS");
  const int kDatasets = env ? std::max(1, std::atoi(env)) : 20;
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  int covered = 0;
  double se_sum = 0;
  for (int d = 0; d < kDatasets; ++d) {
    const data::LabDataset lab = GenerateSyntheticLab(BlockLab(1000 + d), Quiet());
    const CalibrationResult r =
        Fit(scene, lab, KappaFromTime(), "test", 2000 + d, 24, Quiet());
    ASSERT_TRUE(r.covariance_ok) << "dataset " << d << "\n" << r.ceres_full;
    const FittedParameter& k = r.parameters[0];
    const bool holds = k.ci.lower <= kKappaTrue && kKappaTrue <= k.ci.upper;
    covered += holds;
    se_sum += k.standard_error;
    std::printf(
        "dataset %d: kappa %.1f +- %.1f (95 %%: [%.1f, %.1f]) %s, %d evaluations\n", d,
        k.estimate, k.standard_error, k.ci.lower, k.ci.upper, holds ? "holds" : "misses",
        r.evaluations);
  }
  std::printf(
      "coverage of kappa_true = %.0f N/m: %d of %d 95 %% intervals; mean se %.1f N/m\n",
      kKappaTrue, covered, kDatasets, se_sum / kDatasets);
  EXPECT_GE(covered, env ? static_cast<int>(0.85 * kDatasets) : 17);
}

TEST(Calibration, BoundsThatAdmitABrokenSceneAreNamed) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  CalibrationSpec spec;
  // D1 = 3 arm lengths lies beyond D2 = 0.39 h: not a reach curve.
  const std::vector<ParameterSpec> parameters = {
      {"reach/d1_arm_fraction", 3.0, 2.0, 4.0, "/parameters/0"}};
  try {
    WithParameters(scene, parameters, {3.0}, "calib.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "calib.json");
    EXPECT_NE(std::string(e.what()).find("reach/d1_arm_fraction = 3"), std::string::npos)
        << e.what();
  }
}

TEST(Calibration, ATargetTheLabCannotSupplyIsAnInputError) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(BlockLab(9), Quiet());
  CalibrationSpec spec = KappaFromTime();
  spec.stages[0].targets = {
      {"assembly_time", "piston_rod", false, "/targets/0", 0, 0, ""}};
  EXPECT_THROW(Calibrate(scene, lab, spec, "calib.json", 1, 4, Quiet()), InputError);
}

// A lab operator whose stature and arm length the scene's reach curve cannot
// take (D1 = 0.85 arm > D2 = 0.39 height) is an input error naming the row,
// before any simulation, not an abort inside the human model.
TEST(Calibration, ALabOperatorTheReachCurveCannotTakeIsNamed) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  data::LabDataset lab;
  lab.folder = "lab";
  lab.trials_file = "trials.csv";
  data::LabTrial t;
  t.operator_id = "long arms";
  t.sex = "male";
  t.height = 1.5;
  t.arm_length = 0.9;
  t.part = "block";
  t.success = 1;
  t.time = 1.0;
  t.line = 4;
  lab.trials = {t};
  try {
    LabConditions(scene, lab, 3);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "lab/trials.csv");
    EXPECT_EQ(e.where(), "line 4, operator long arms");
  }
}

}  // namespace
}  // namespace vahf::calibrate
