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

#include "support/quiet_runner.h"
#include "vahf/calibrate/synthetic_lab.h"
#include "vahf/core/error.h"
#include "vahf/experiment/design.h"
#include "vahf/human/factor_curves.h"
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
  spec.stages[0].parameters = {
      {"guidance/kappa", 400.0, 50.0, 2000.0, "/parameters/0", ""}};
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

experiment::RunnerOptions Quiet() { return testing::QuietRunner(); }

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
  // The estimate's Monte Carlo spread over other virtual people: part of its
  // standard error (the lab's own variance is the rest), not none of it.
  EXPECT_EQ(r.noise_replicates, 4);
  EXPECT_GT(k.mc_sd, 0.0);
  EXPECT_LT(k.mc_sd, k.standard_error);
}

// A calibration started from its own estimate (an override file's value is
// the start, docs/calibration.md "A fixed point") ends within its fixed-point
// tolerance of it: a Levenberg-Marquardt stage and a golden-section one.
TEST(Calibration, StartedFromItsOwnEstimateItEndsThere) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(BlockLab(101), Quiet());
  for (const char* solver : {"levenberg_marquardt", "golden_section"}) {
    CalibrationSpec spec = KappaFromTime();
    spec.noise_replicates = 0;
    spec.stages[0].solver = solver;
    const CalibrationResult first = Fit(scene, lab, spec, "test", 7, 6, Quiet());
    EXPECT_TRUE(first.parameters[0].start_from.empty());
    EXPECT_TRUE(std::isnan(first.parameters[0].fixed_point_change));
    spec.stages[0].parameters[0].start = first.parameters[0].estimate;
    spec.stages[0].parameters[0].start_from = "calibrated.json";
    const CalibrationResult again = Fit(scene, lab, spec, "test", 7, 6, Quiet());
    const FittedParameter& k = again.parameters[0];
    EXPECT_EQ(k.start_from, "calibrated.json") << solver;
    EXPECT_EQ(k.start, first.parameters[0].estimate) << solver;
    EXPECT_EQ(k.fixed_point_change, std::abs(k.estimate - k.start)) << solver;
    EXPECT_LE(k.fixed_point_change, k.fixed_point_tolerance) << solver;
    // The tolerance is the solver's, not a blanket: a tenth of the standard
    // error (LM, whose weights re-settle) or the bracket (golden section).
    EXPECT_LE(k.fixed_point_tolerance, 0.02 * k.estimate) << solver;
  }
}

TEST(Calibration, NoReplicatesNoMonteCarloSpread) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(BlockLab(101), Quiet());
  CalibrationSpec spec = KappaFromTime();
  spec.noise_replicates = 0;
  const CalibrationResult r = Fit(scene, lab, spec, "test", 7, 6, Quiet());
  EXPECT_EQ(r.noise_replicates, 0);
  EXPECT_TRUE(std::isnan(r.parameters[0].mc_sd));
}

// A target with pooled variances ("variance": "pooled") weighs each of its
// operators by one variance on each side, the lab's and the virtual one
// (PoolVariances, at every design evaluation): their n x variance is the
// same for both operators, at the start and at the fit; without it the
// operators' own differ.
TEST(Calibration, APooledTargetWeighsEveryOperatorByOneVarianceOnEachSide) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(BlockLab(101), Quiet());
  CalibrationSpec spec = KappaFromTime();
  spec.stages[0].targets[0].by_operator = true;
  spec.noise_replicates = 0;
  const auto per_trial = [](const Statistic& s) { return s.variance * s.n; };
  const CalibrationResult own = Fit(scene, lab, spec, "test", 7, 6, Quiet());
  ASSERT_EQ(own.targets.size(), 2u);
  EXPECT_GT(std::abs(per_trial(own.targets[0].target.lab) /
                         per_trial(own.targets[1].target.lab) -
                     1),
            0.05);
  spec.stages[0].targets[0].pooled_variance = true;
  const CalibrationResult pooled = Fit(scene, lab, spec, "test", 7, 6, Quiet());
  ASSERT_EQ(pooled.targets.size(), 2u);
  const FittedTarget& a = pooled.targets[0];
  const FittedTarget& b = pooled.targets[1];
  EXPECT_DOUBLE_EQ(per_trial(a.target.lab), per_trial(b.target.lab));
  EXPECT_DOUBLE_EQ(per_trial(a.start), per_trial(b.start));
  EXPECT_DOUBLE_EQ(per_trial(a.fitted), per_trial(b.fitted));
  // Equal counts: the pooled variance is the mean of the operators' own.
  EXPECT_NEAR(
      per_trial(a.target.lab),
      0.5 * (per_trial(own.targets[0].target.lab) + per_trial(own.targets[1].target.lab)),
      1e-12);
  EXPECT_TRUE(pooled.covariance_ok);
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

// The lab's tallest and shortest operators: GB/T 10000-1988, the P95 man
// (18-60) and the P5 woman (18-55), as data/synthetic_block has them. At the
// paper's fractions D1 = 0.85 arm and D2 = 0.39 stature are 0.673 m and
// 0.692 m for the man: a 5 % step of D1's fraction passes D2.
SyntheticLabSpec ReachLab(std::uint64_t seed, const human::ReachCurve& reach) {
  SyntheticLabSpec spec = BlockLab(seed);
  spec.scene.params.reach = reach;
  spec.truth.emplace_back("reach/d1_arm_fraction", reach.d1_arm_fraction);
  spec.truth.emplace_back("reach/d2_height_fraction", reach.d2_height_fraction);
  spec.truth.emplace_back("reach/d3_height_fraction", reach.d3_height_fraction);
  spec.operators = {{"male P95", "male", 1.775, 0.792, "GB/T 10000-1988"},
                    {"female P5", "female", 1.484, 0.614, "GB/T 10000-1988"}};
  spec.repetitions = 8;
  return spec;
}

// D1-D3 (start, lower, upper each) and kappa, to each operator's mean time.
CalibrationSpec ReachAndKappa(const std::vector<ParameterSpec>& reach) {
  CalibrationSpec spec = KappaFromTime();
  std::vector<ParameterSpec> all = reach;
  all.push_back({"guidance/kappa", 400.0, 50.0, 2000.0, "/parameters/3", ""});
  spec.stages[0].parameters = all;
  spec.stages[0].targets[0].by_operator = true;
  return spec;
}

// A joint fit of D1-D3 and kappa runs to its end where a difference step
// would break D1 < D2 < D3 for the tallest operator: the first Jacobian's
// step of D1's fraction to 0.8925 does (0.707 m > 0.692 m), and before the
// feasible differences the fit stopped there with an input error.
TEST(Calibration, AJointFitOfReachAndKappaRunsToItsEndAtTheRulesEdge) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(ReachLab(31, {}), Quiet());
  const CalibrationSpec spec =
      ReachAndKappa({{"reach/d1_arm_fraction", 0.85, 0.5, 1.2, "/parameters/0", ""},
                     {"reach/d2_height_fraction", 0.39, 0.3, 0.6, "/parameters/1", ""},
                     {"reach/d3_height_fraction", 0.68, 0.5, 0.9, "/parameters/2", ""}});
  CalibrationResult r;
  ASSERT_NO_THROW(r = Fit(scene, lab, spec, "test", 7, 8, Quiet()));
  EXPECT_GT(r.differences.one_sided, 0) << r.ceres_full;
  EXPECT_EQ(r.differences.failed, 0);
  human::ReachCurve fitted;
  fitted.d1_arm_fraction = r.parameters[0].estimate;
  fitted.d2_height_fraction = r.parameters[1].estimate;
  fitted.d3_height_fraction = r.parameters[2].estimate;
  for (const auto& op : ReachLab(31, {}).operators)
    EXPECT_EQ(fitted.Violation(op.arm_length, op.height), "") << op.name;
  EXPECT_GT(r.parameters[3].estimate, 50.0);
  EXPECT_LT(r.parameters[3].estimate, 2000.0);
}

// The golden-section search walks D1's fraction up to its bound 1.2, past
// the rule's edge for the P95 man (0.39 x 1.775 / 0.792 = 0.874): the points
// beyond count as no cost, and its profile interval closes before the edge.
TEST(Calibration, AGoldenSectionSearchWalksUpToTheRulesEdgeAndStops) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(ReachLab(37, {}), Quiet());
  CalibrationSpec spec = KappaFromTime();
  spec.stages[0].solver = "golden_section";
  spec.stages[0].parameters = {
      {"reach/d1_arm_fraction", 0.6, 0.5, 1.2, "/parameters/0", ""}};
  spec.stages[0].targets[0].by_operator = true;
  CalibrationResult r;
  ASSERT_NO_THROW(r = Fit(scene, lab, spec, "test", 7, 8, Quiet()));
  const double edge = 0.39 * 1.775 / 0.792;
  EXPECT_LT(r.parameters[0].estimate, edge) << r.search_log;
  EXPECT_GT(r.refused, 0) << r.search_log;
  EXPECT_LT(r.parameters[0].profile.upper, edge) << r.search_log;
}

// A stage with targets of both kinds, each operator's time and the success
// rate of two segments of an hour of work, runs both virtual designs at each
// parameter vector: the lab's operators on the first stream indices, the
// fatigue design after them, so that the two kinds are independent
// residuals. Its start statistics are those of the two designs run here.
TEST(Calibration, AStageOfTimesAndSegmentsRunsBothDesignsOnStreamsOfTheirOwn) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  data::LabDataset lab = GenerateSyntheticLab(BlockLab(41), Quiet());
  for (int s = 1; s <= 2; ++s) {
    data::LabSegment seg;
    seg.segment = s;
    seg.start_min = 5.0 * (s - 1);
    seg.end_min = 5.0 * s;
    seg.attempts = 10;
    seg.successes = s == 1 ? 9 : 7;
    seg.line = s + 1;
    lab.segments.push_back(seg);
  }
  lab.segments_file = "segments.csv";
  CalibrationSpec spec = KappaFromTime();
  spec.stages[0].parameters.push_back(
      {"fatigue/a_max", 20000.0, 500.0, 1e6, "/parameters/1", ""});
  spec.stages[0].targets[0].by_operator = true;
  for (int s = 1; s <= 2; ++s) {
    TargetSpec t;
    t.quantity = "success_rate";
    t.part = "all";
    t.segment = s;
    t.pointer = "/targets/" + std::to_string(s);
    spec.stages[0].targets.push_back(t);
  }
  spec.fatigue = {10.0, 2, 2};
  spec.max_iterations = 2;
  spec.noise_replicates = 0;
  constexpr int kTrials = 4;
  const CalibrationResult r = Fit(scene, lab, spec, "test", 7, kTrials, Quiet());
  ASSERT_EQ(r.targets.size(), 4u);  // two operators' times, two segments

  scene::Scene start = scene;
  start.params.guidance.kappa = 400.0;
  start.params.fatigue.a_max = 20000.0;
  const std::vector<Target> targets =
      LabTargets(scene, lab, spec.stages[0].targets, "test");
  const std::vector<experiment::Condition> operators = LabConditions(start, lab, kTrials);
  const experiment::DesignRun run =
      experiment::RunDesign(operators, kTrials, 7, false, Quiet());
  const experiment::FatigueRun hour = experiment::RunFatigue(
      std::make_shared<const scene::Scene>(start), spec.fatigue, kTrials, 7, Quiet(),
      Quiet(), {0, 1}, operators.size() * kTrials);
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_EQ(r.targets[i].start.value, VirtualStatistic(targets[i], run).value) << i;
  for (std::size_t i = 2; i < 4; ++i)
    EXPECT_EQ(r.targets[i].start.value,
              VirtualStatistic(targets[i], hour.run, hour.segments).value)
        << i;
  // On the first stream indices instead, the hour's cycles would repeat the
  // operators' draws: the pilot's and segments' first cycles are not those.
  const experiment::FatigueRun shared =
      experiment::RunFatigue(std::make_shared<const scene::Scene>(start), spec.fatigue,
                             kTrials, 7, Quiet(), Quiet(), {0, 1});
  EXPECT_NE(shared.run.records[0].result.time, hour.run.records[0].result.time);
}

// Fractions at which every operator's reach stays on its plateau (D1 beyond
// the arm's length): no target moves with them.
human::ReachCurve FlatReach() {
  human::ReachCurve reach;
  reach.d1_arm_fraction = 1.1;
  reach.d2_height_fraction = 0.62;
  reach.d3_height_fraction = 0.8;
  return reach;
}

// D1-D3 that move no target are named as not identified, with no interval;
// kappa, which the times determine, keeps its interval (with the D's held),
// and it holds the truth. Before, Ceres' covariance was rank deficient and
// no parameter had an interval.
TEST(Calibration, ReachThatMovesNoTargetIsNotIdentifiedAndKappaKeepsItsInterval) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(ReachLab(33, FlatReach()), Quiet());
  const CalibrationSpec spec =
      ReachAndKappa({{"reach/d1_arm_fraction", 1.1, 1.0, 1.3, "/parameters/0", ""},
                     {"reach/d2_height_fraction", 0.62, 0.6, 0.7, "/parameters/1", ""},
                     {"reach/d3_height_fraction", 0.8, 0.75, 0.9, "/parameters/2", ""}});
  const CalibrationResult r = Fit(scene, lab, spec, "test", 7, 12, Quiet());
  EXPECT_EQ(r.rank.rank, 1) << r.rank.singular_values.transpose();
  for (int i = 0; i < 3; ++i) {
    const FittedParameter& d = r.parameters[static_cast<std::size_t>(i)];
    EXPECT_FALSE(d.identified) << d.name;
    EXPECT_NE(d.not_identified_why.find("null space"), std::string::npos)
        << d.not_identified_why;
    EXPECT_TRUE(std::isnan(d.standard_error)) << d.name;
    EXPECT_TRUE(std::isnan(d.ci.lower) && std::isnan(d.ci.upper)) << d.name;
  }
  const FittedParameter& k = r.parameters[3];
  ASSERT_TRUE(k.identified) << k.not_identified_why;
  ASSERT_TRUE(r.covariance_ok);
  EXPECT_GT(k.standard_error, 0.0);
  EXPECT_LE(k.ci.lower, kKappaTrue) << r.ceres_brief;
  EXPECT_GE(k.ci.upper, kKappaTrue) << r.ceres_brief;
  EXPECT_LT(k.ci.upper, 400.0);
}

// With "intervals": "profile" the same fit gives kappa its profile interval
// too, the D's none (not identified, so not re-fitted either): the cost of
// kappa alone is nearly quadratic here, so the profile lies within a few
// percent of the Wald interval's ends and holds the truth, and no re-fit
// found a cost below the estimate's.
TEST(Calibration, AProfileStageGivesTheIdentifiedTheirProfileIntervalsOnly) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(ReachLab(33, FlatReach()), Quiet());
  CalibrationSpec spec =
      ReachAndKappa({{"reach/d1_arm_fraction", 1.1, 1.0, 1.3, "/parameters/0", ""},
                     {"reach/d2_height_fraction", 0.62, 0.6, 0.7, "/parameters/1", ""},
                     {"reach/d3_height_fraction", 0.8, 0.75, 0.9, "/parameters/2", ""}});
  spec.intervals = "profile";
  const CalibrationResult r = Fit(scene, lab, spec, "test", 7, 12, Quiet());
  for (int i = 0; i < 3; ++i) {
    EXPECT_FALSE(r.parameters[static_cast<std::size_t>(i)].identified);
    EXPECT_FALSE(r.parameters[static_cast<std::size_t>(i)].has_profile);
  }
  const FittedParameter& k = r.parameters[3];
  ASSERT_TRUE(k.has_profile);
  EXPECT_TRUE(k.profile_reached);
  EXPECT_FALSE(k.profile_open_lower || k.profile_open_upper);
  EXPECT_LE(k.profile.lower, kKappaTrue);
  EXPECT_GE(k.profile.upper, kKappaTrue);
  const double half = k.ci.upper - k.estimate;
  EXPECT_NEAR(k.profile.upper - k.estimate, half, 0.15 * half);
  EXPECT_NEAR(k.estimate - k.profile.lower, half, 0.15 * half);
  EXPECT_GE(k.profile_points.size(), 3u);
  EXPECT_GE(r.profile_least_rise, -0.1);
}

// A start that breaks the rule is an input error naming the experiment
// file, the start and the operator.
TEST(Calibration, AStartThatBreaksTheReachRuleIsNamed) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab = GenerateSyntheticLab(ReachLab(35, {}), Quiet());
  const CalibrationSpec spec =
      ReachAndKappa({{"reach/d1_arm_fraction", 0.9, 0.5, 1.2, "/parameters/0", ""},
                     {"reach/d2_height_fraction", 0.39, 0.3, 0.6, "/parameters/1", ""},
                     {"reach/d3_height_fraction", 0.68, 0.5, 0.9, "/parameters/2", ""}});
  try {
    Calibrate(scene, lab, spec, "calib.json", 1, 2, Quiet());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "calib.json");
    const std::string what = e.what();
    EXPECT_NE(what.find("reach/d1_arm_fraction 0.9"), std::string::npos) << what;
    EXPECT_NE(what.find("operator male P95"), std::string::npos) << what;
  }
}

TEST(Calibration, BoundsThatAdmitABrokenSceneAreNamed) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  CalibrationSpec spec;
  // D1 = 3 arm lengths lies beyond D2 = 0.39 h: not a reach curve.
  const std::vector<ParameterSpec> parameters = {
      {"reach/d1_arm_fraction", 3.0, 2.0, 4.0, "/parameters/0", ""}};
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
