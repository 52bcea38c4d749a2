// A quantity's comparison from its two samples, or against what a lab
// reports (hand-computed differences, standard errors, TOST p and area
// metrics): the verdicts and the sentences that carry them. The lab's side of
// a comparison file's quantities (LabSide), and which virtual designs a
// comparison runs.
#include "vahf/compare/comparison.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "vahf/core/error.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/kinds/kind.h"
#include "vahf/report/compare_section.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/stats/proportion.h"

namespace vahf::compare {
namespace {

std::string Path(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A scene for LabSide: its curves measure a lab's tracks (none here but in
// the eta tests below).
const scene::Scene& BlockScene() {
  static const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  return scene;
}

calibrate::Target TimeTarget() {
  calibrate::Target t;
  t.spec.quantity = "assembly_time";
  t.spec.part = "peg";
  t.unit = "s";
  t.label = "assembly_time of peg";
  return t;
}

calibrate::TargetSamples Times(const std::vector<double>& times) {
  calibrate::TargetSamples s;
  for (double x : times) s.Add(true, x, "op");
  return s;
}

TEST(CompareSamples, TimesWithinTheMarginAgree) {
  const auto lab = Times({1.00, 1.02, 0.98, 1.01, 0.99, 1.00});
  const auto virt = Times({1.01, 1.00, 0.99, 1.02, 1.00, 0.98});
  const QuantityComparison q = CompareSamples(TimeTarget(), 0.05, lab, virt);
  ASSERT_TRUE(q.testable);
  EXPECT_TRUE(q.agree) << q.verdict;
  EXPECT_EQ(q.verdict.rfind("agree:", 0), 0u) << q.verdict;
  EXPECT_LT(q.tost_p, 0.05);
  ASSERT_TRUE(q.ks.has_value());
  EXPECT_GE(q.area_metric, 0.0);
}

TEST(CompareSamples, ADifferenceBeyondTheMarginIsNotShownToAgree) {
  const auto lab = Times({1.00, 1.02, 0.98, 1.01, 0.99, 1.00});
  const auto virt = Times({0.80, 0.82, 0.78, 0.81, 0.79, 0.80});
  const QuantityComparison q = CompareSamples(TimeTarget(), 0.05, lab, virt);
  EXPECT_FALSE(q.agree);
  EXPECT_EQ(q.verdict.rfind("not shown to agree:", 0), 0u) << q.verdict;
  EXPECT_NEAR(q.difference, -0.2, 1e-12);
  EXPECT_NEAR(q.area_metric, 0.2, 1e-12);  // a pure shift: the area is the shift
}

TEST(CompareSamples, TooFewTimesAreUntestableAndSaySo) {
  const QuantityComparison q =
      CompareSamples(TimeTarget(), 0.05, Times({1.0}), Times({1.0, 1.1, 0.9}));
  EXPECT_FALSE(q.testable);
  EXPECT_EQ(q.verdict.rfind("untestable:", 0), 0u) << q.verdict;
  EXPECT_NE(q.verdict.find("1 lab"), std::string::npos) << q.verdict;
}

// Times that do not vary on either side leave no t statistic: untestable, and
// it says why. Only that refusal is a verdict; a margin outside the test's
// domain is the caller's to fix, and reaches it.
TEST(CompareSamples, ZeroVarianceOnBothSidesIsUntestable) {
  const QuantityComparison q =
      CompareSamples(TimeTarget(), 0.05, Times({1.0, 1.0, 1.0}), Times({1.2, 1.2}));
  EXPECT_FALSE(q.testable);
  EXPECT_EQ(q.verdict.rfind("untestable: both samples have zero variance", 0), 0u)
      << q.verdict;
  try {
    CompareSamples(TimeTarget(), 0.0, Times({1.0, 1.0, 1.0}), Times({1.2, 1.2}));
    ADD_FAILURE() << "a zero margin was taken for zero variance";
  } catch (const ComputationError& e) {
    EXPECT_EQ(e.reason(), ComputationError::Reason::kOutOfDomain) << e.what();
  }
}

TEST(CompareSamples, RatesAgreeOnlyWhenTheDataResolveTheMargin) {
  calibrate::Target t = TimeTarget();
  t.spec.quantity = "success_rate";
  t.unit = "1";
  calibrate::TargetSamples few_lab, few_virt, many_lab, many_virt;
  for (int i = 0; i < 10; ++i)
    few_lab.Add(i < 9, 1.0, "op"), few_virt.Add(i < 9, 1.0, "op");
  for (int i = 0; i < 1000; ++i)
    many_lab.Add(i < 900, 1.0, "op"), many_virt.Add(i < 900, 1.0, "op");
  // Equal rates of 0.9: ten trials a side cannot show agreement within 0.1,
  // a thousand can.
  EXPECT_FALSE(CompareSamples(t, 0.1, few_lab, few_virt).agree);
  const QuantityComparison many = CompareSamples(t, 0.1, many_lab, many_virt);
  EXPECT_TRUE(many.agree) << many.verdict;
  EXPECT_DOUBLE_EQ(many.difference, 0.0);
  EXPECT_FALSE(many.ks.has_value());
}

// ---------------------------------------------------------------------------
// Against a reported value: the normal approximation.

calibrate::Target Reported(const std::string& quantity, double value, double variance,
                           int n, bool single_draw = false) {
  calibrate::Target t = TimeTarget();
  t.spec.quantity = quantity;
  t.unit = quantity == "assembly_time" ? "s" : "1";
  t.label = quantity + " of peg";
  t.lab.value = value;
  t.lab.variance = variance;
  t.lab.n = n;
  t.lab.single_draw = single_draw;
  return t;
}

// Virtual times 1.0, 1.2, 1.4, 1.6: mean 1.3, s^2 = 0.2 / 3, variance of the
// mean s^2 / 4 = 1/60. The lab reports 1.5 s with variance 0.01 (sd 0.2, n 4).
TEST(CompareReported, ATimeAgainstAReportedMeanByHand) {
  const auto virt = Times({1.0, 1.2, 1.4, 1.6});
  const QuantityComparison q =
      CompareReported(Reported("assembly_time", 1.5, 0.01, 4), 0.5, virt);
  ASSERT_TRUE(q.testable) << q.verdict;
  EXPECT_TRUE(q.reported);
  const double se = std::sqrt(1.0 / 60 + 0.01);  // 0.163299
  EXPECT_NEAR(q.difference, -0.2, 1e-12);
  EXPECT_NEAR(q.ci95.lower, -0.2 - 1.959963984540054 * se, 1e-12);
  EXPECT_NEAR(q.ci95.upper, -0.2 + 1.959963984540054 * se, 1e-12);
  EXPECT_NEAR(q.ci90.lower, -0.46860347250648926, 1e-12);
  EXPECT_NEAR(q.ci90.upper, 0.06860347250648935, 1e-12);
  // p = max(Q((d + m) / se), P((d - m) / se)) = Q(0.3 / 0.163299) = Q(1.8371).
  EXPECT_NEAR(q.tost_p, 0.033096289861096716, 1e-12);
  EXPECT_TRUE(q.agree) << q.verdict;
  EXPECT_EQ(q.verdict.rfind("agree:", 0), 0u) << q.verdict;
  EXPECT_NE(q.verdict.find("against the value the lab reports"), std::string::npos)
      << q.verdict;
  // Against a step at 1.5 s: (0.5 + 0.3 + 0.1 + 0.1) / 4.
  EXPECT_NEAR(q.area_metric, 0.25, 1e-12);
  EXPECT_NEAR(q.lab_variance, 0.01, 1e-15);
  EXPECT_NEAR(q.lab_ci.lower, 1.5 - 1.959963984540054 * 0.1, 1e-12);
  EXPECT_NEAR(q.lab_ci.upper, 1.5 + 1.959963984540054 * 0.1, 1e-12);
  EXPECT_FALSE(q.ks.has_value());
  EXPECT_EQ(q.ks_unavailable, "the lab reports a summary, not samples");
  // A margin the 90 % interval crosses: not shown to agree.
  const QuantityComparison narrow =
      CompareReported(Reported("assembly_time", 1.5, 0.01, 4), 0.3, virt);
  EXPECT_FALSE(narrow.agree);
  EXPECT_EQ(narrow.verdict.rfind("not shown to agree:", 0), 0u) << narrow.verdict;
}

// A time reported once without a spread (Table 1's 9.2 s) is a draw of the
// population the virtual side samples: its variance is the virtual
// per-sample one, s^2 = 0.2 / 3, so se = sqrt(s^2 / 4 + s^2).
TEST(CompareReported, ASingleDrawIsWeighedByTheVirtualSpread) {
  const QuantityComparison q = CompareReported(
      Reported("assembly_time", 2.0, kNaN, 1, true), 1.0, Times({1.0, 1.2, 1.4, 1.6}));
  ASSERT_TRUE(q.testable) << q.verdict;
  const double s2 = 0.2 / 3;
  EXPECT_NEAR(q.lab_variance, s2, 1e-12);
  EXPECT_NEAR(q.difference, -0.7, 1e-12);
  EXPECT_NEAR(q.ci95.upper - q.ci95.lower, 2 * 1.959963984540054 * std::sqrt(s2 / 4 + s2),
              1e-12);
  EXPECT_NEAR(q.tost_p, 0.14934877799748508, 1e-12);  // Q(0.3 / 0.288675)
  EXPECT_FALSE(q.agree);
  EXPECT_NEAR(q.lab_ci.lower, 2.0 - 1.959963984540054 * std::sqrt(s2), 1e-12);
  EXPECT_NEAR(q.area_metric, 0.7, 1e-12);  // every virtual time lies below 2 s
  EXPECT_NE(q.verdict.find("single draw"), std::string::npos) << q.verdict;
  // One virtual time has no spread to lend: untestable, and it says why.
  const QuantityComparison one =
      CompareReported(Reported("assembly_time", 2.0, kNaN, 1, true), 1.0, Times({1.3}));
  EXPECT_FALSE(one.testable);
  EXPECT_EQ(one.verdict.rfind("untestable: 1 virtual", 0), 0u) << one.verdict;
}

// 18 of 20 virtual cycles succeed (0.9; Laplace p = 19/22, variance p (1 - p)
// / 20); the lab reports 0.8 over n = 10 (p = 9/12, variance 0.01875).
TEST(CompareReported, ARateAgainstAReportedRateWithItsCount) {
  data::LabDataset lab;
  lab.file = "lab/dataset.json";
  lab.summaries_file = "summaries.csv";
  data::LabSummary row;
  row.quantity = "success_rate";
  row.part = "peg";
  row.condition = "real";
  row.segment = 1;
  row.value = 0.8;
  row.n = 10;
  row.line = 2;
  lab.summaries = {row};
  ComparisonDesign design;
  design.quantities = {{"success_rate", "peg", false, "/quantities/0", 0.3, 1, "real"}};
  const std::vector<LabQuantity> side = LabSide(BlockScene(), lab, design, "e.json");
  ASSERT_EQ(side.size(), 1u);
  ASSERT_TRUE(side[0].reported);
  EXPECT_NEAR(side[0].target.lab.variance, 0.01875, 1e-15);
  calibrate::TargetSamples virt;
  for (int i = 0; i < 20; ++i) virt.Add(i < 18, 1.0, "op");
  const QuantityComparison q = CompareReported(side[0].target, 0.3, virt);
  ASSERT_TRUE(q.testable) << q.verdict;
  EXPECT_NEAR(q.difference, 0.1, 1e-12);
  const double pv = 19.0 / 22;
  const double se = std::sqrt(0.01875 + pv * (1 - pv) / 20);  // 0.156966
  EXPECT_NEAR(q.ci90.lower, 0.1 - 1.6448536269514722 * se, 1e-12);
  EXPECT_NEAR(q.tost_p, 0.10130361077415184, 1e-12);  // P(-0.2 / se)
  EXPECT_FALSE(q.agree);
  EXPECT_NEAR(q.area_metric, 0.1, 1e-12);
  // The lab's interval, 0.8 +- 1.96 sqrt(0.01875), stays within [0, 1].
  EXPECT_NEAR(q.lab_ci.lower, 0.5316208784424266, 1e-12);
  EXPECT_DOUBLE_EQ(q.lab_ci.upper, 1.0);
  EXPECT_EQ(q.virtual_ci.lower, stats::WilsonInterval({18, 20}).lower);
}

TEST(CompareReported, AValueWithoutAnySpreadIsShownAndUntestable) {
  const QuantityComparison q = CompareReported(Reported("assembly_time", 16, kNaN, 0),
                                               1.0, Times({1.0, 1.2, 1.4, 1.6}));
  EXPECT_FALSE(q.testable);
  EXPECT_EQ(q.verdict.rfind("untestable: the lab reports 16 s without sd and n", 0), 0u)
      << q.verdict;
  EXPECT_FALSE(std::isfinite(q.lab_ci.lower));
  EXPECT_DOUBLE_EQ(q.target.lab.value, 16);  // the point is kept for the report
  EXPECT_NEAR(q.virtual_stat.value, 1.3, 1e-12);
}

// ---------------------------------------------------------------------------
// The lab's side: trials, or what the lab reports.

scene::FitTarget Spec(const std::string& quantity, int segment,
                      const std::string& condition,
                      const std::string& pointer = "/quantities/0") {
  return {quantity, "all", false, pointer, 0.1, segment, condition};
}

TEST(LabSide, ReadsWhatThePaperReports) {
  const data::LabDataset lab = data::LoadLabDataset(Path("data/paper/dataset.json"));
  const scene::ExperimentFile file =
      kinds::LoadExperiment(Path("experiments/compare_paper.json"));
  const std::vector<LabQuantity> side =
      LabSide(file.scene, lab, file.Input<ComparisonDesign>(), file.file);
  ASSERT_EQ(side.size(), 6u);
  for (const LabQuantity& q : side) EXPECT_TRUE(q.reported) << q.target.label;
  // Table 1's 9.2 s: one run without a spread.
  EXPECT_DOUBLE_EQ(side[0].target.lab.value, 9.2);
  EXPECT_TRUE(side[0].target.lab.single_draw);
  EXPECT_EQ(LabBasis(side[0].target, true), "reported once, no spread (a single draw)");
  // No condition: the row without one, "about 16 s", not the virtual 9.2 s
  // that comes first in the file.
  EXPECT_DOUBLE_EQ(side[1].target.lab.value, 16);
  EXPECT_FALSE(side[1].target.lab.single_draw);
  EXPECT_FALSE(std::isfinite(side[1].target.lab.variance));
  EXPECT_EQ(LabBasis(side[1].target, true), "reported, no spread");
  EXPECT_EQ(side[1].target.label, "assembly_time of all");
  // The rates of five users: p (1 - p) / 5 with p = (5 value + 1) / 7.
  const double expected[] = {0.92, 0.96, 0.68, 0.75};
  for (int k = 0; k < 4; ++k) {
    const calibrate::Statistic& l = side[static_cast<std::size_t>(k) + 2].target.lab;
    EXPECT_DOUBLE_EQ(l.value, expected[k]);
    EXPECT_EQ(l.n, 5);
    const double p = (expected[k] * 5 + 1) / 7;
    EXPECT_NEAR(l.variance, p * (1 - p) / 5, 1e-15);
  }
  EXPECT_EQ(side[2].target.label, "success_rate of all, segment 1, real");
}

TEST(LabSide, SeveralConditionsAndNoneNamedIsAnInputError) {
  const data::LabDataset lab = data::LoadLabDataset(Path("data/paper/dataset.json"));
  ComparisonDesign design;
  design.quantities = {Spec("success_rate", 4, "", "/quantities/3")};
  try {
    LabSide(BlockScene(), lab, design, "e.json");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "e.json");
    EXPECT_EQ(e.where(), "/quantities/3/condition");
    EXPECT_NE(e.rule().find("condition 'virtual'"), std::string::npos) << e.what();
    EXPECT_NE(e.rule().find("'real'"), std::string::npos) << e.what();
    EXPECT_NE(e.rule().find("name the one to read"), std::string::npos) << e.what();
  }
}

TEST(LabSide, NeitherTrialsNorAReportIsAnInputError) {
  const data::LabDataset lab = data::LoadLabDataset(Path("data/paper/dataset.json"));
  ComparisonDesign design;
  design.quantities = {Spec("success_rate", 2, "real")};  // Fig. 16 only: not in the file
  try {
    LabSide(BlockScene(), lab, design, "e.json");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/quantities/0");
    EXPECT_NE(e.rule().find("reports no success_rate of segment 2"), std::string::npos)
        << e.what();
  }
  design.quantities = {Spec("assembly_time", 0, "")};
  design.quantities[0].by_operator = true;  // the paper has no trials, so no operators
  try {
    LabSide(BlockScene(), lab, design, "e.json");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/quantities/0/by");
    EXPECT_NE(e.rule().find("no trials, hence no operators"), std::string::npos)
        << e.what();
  }
}

// ---------------------------------------------------------------------------
// Which virtual designs a comparison runs: the lab's operators only for
// quantities without a segment, the hour of work only for segment ones.

TEST(Compare, RunsEachDesignOnlyWhenAQuantityNeedsIt) {
  experiment::RunnerOptions quiet;
  quiet.threads = 2;
  quiet.progress = false;
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  data::LabDataset lab = data::LoadLabDataset(Path("data/synthetic_block/dataset.json"));
  data::LabSegment segment;
  segment.segment = 2;
  segment.start_min = 15;
  segment.end_min = 30;
  segment.attempts = 20;
  segment.successes = 19;
  lab.segments = {segment};
  lab.segments_file = "segments.csv";
  ComparisonDesign design;
  design.fatigue = {60, 4, 2};
  const scene::FitTarget time = {
      "assembly_time", "block", false, "/quantities/0", 0.03, 0, ""};
  const scene::FitTarget rate = {
      "success_rate", "all", false, "/quantities/1", 0.1, 2, ""};
  const int trials = 3;

  design.quantities = {rate};
  ComparisonResult r = Compare(scene, lab, design, "e.json", 5, trials, quiet, quiet);
  EXPECT_TRUE(r.run.conditions.empty());
  EXPECT_EQ(r.fatigue.segments, std::vector<int>{1});
  EXPECT_EQ(r.fatigue.pilot.records.size(), 2u);
  ASSERT_EQ(r.quantities.size(), 1u);
  EXPECT_TRUE(r.quantities[0].reported);
  EXPECT_EQ(r.quantities[0].virt.attempts, trials);
  EXPECT_DOUBLE_EQ(r.quantities[0].target.lab.value, 0.95);

  design.quantities = {time, rate};
  r = Compare(scene, lab, design, "e.json", 5, trials, quiet, quiet);
  EXPECT_EQ(r.run.conditions.size(), 6u);  // the lab's six operators
  EXPECT_EQ(r.fatigue.segments, std::vector<int>{1});
  ASSERT_EQ(r.quantities.size(), 2u);
  EXPECT_FALSE(r.quantities[0].reported);
  EXPECT_EQ(r.quantities[0].virt.attempts, 6 * trials);
  EXPECT_EQ(r.quantities[1].virt.attempts, trials);

  design.quantities = {time};
  r = Compare(scene, lab, design, "e.json", 5, trials, quiet, quiet);
  EXPECT_EQ(r.run.conditions.size(), 6u);
  EXPECT_TRUE(r.fatigue.run.conditions.empty());
  EXPECT_TRUE(r.fatigue.pilot.records.empty());
}

// ---------------------------------------------------------------------------
// eta at an instant from the lab's sensor tracks, against the virtual
// trials' decision traces, in the comparison and its report.

// The operator stands facing +x, the head over the left shoulder; the part is
// lowered 0.4 m from level with the brow, 0.4 m ahead, by t = 0.5 s. The
// sight line (0.4, 0, -0.4) meets the motion (0, 0, -1) at 45 deg: f = 1 on
// the default sight curve's plateau (Fig. 3), so eta = 1 - V (Eq. 2) at the
// sample of 0.5 s, held to the next at 1.0 s (tests/calibrate/
// track_targets_test.cc has the factors in full).
data::SensorTrack LoweredPart(int repetition, double V) {
  data::SensorTrack t;
  t.file = fmt::format("tracks/{}.csv", repetition);
  t.operator_id = "male 1";
  t.condition = "standard";
  t.repetition = repetition;
  for (int i = 0; i < 3; ++i) {
    data::TrackSample s;
    s.time = 0.5 * i;
    s.part = Eigen::Vector3d(0, 0, i == 0 ? 0.4 : 0.0);
    s.brow = Eigen::Vector3d(-0.4, 0, 0.4);
    s.left_shoulder = Eigen::Vector3d(-0.5, 0, 0.2);
    s.right_shoulder = Eigen::Vector3d(-0.5, -0.4, 0.2);
    s.body = Eigen::Vector3d(-0.5, -0.2, -0.2);
    s.visibility = i == 0 ? 1.0 : V;
    s.line = i + 2;
    t.samples.push_back(s);
  }
  return t;
}

TEST(Compare, ReadsEtaFromTracksAndReportsIt) {
  experiment::RunnerOptions quiet;
  quiet.threads = 2;
  quiet.progress = false;
  const scene::Scene scene = BlockScene();
  data::LabDataset lab;
  lab.file = "lab/dataset.json";
  lab.name = "tracks";
  lab.provenance = {{"source", "written by hand for this test"}};
  lab.trials_file = "trials.csv";
  for (int k = 1; k <= 3; ++k) {
    data::LabTrial t;
    t.operator_id = "male 1";
    t.sex = "male";
    t.height = 1.75;
    t.arm_length = 0.74;
    t.condition = "standard";
    t.part = "block";
    t.repetition = k;
    t.time = 1.0;
    t.success = 1;
    t.line = k + 1;
    lab.trials.push_back(t);
  }
  lab.tracks = {LoweredPart(1, 0.9), LoweredPart(2, 0.8), LoweredPart(3, 0.4)};
  ComparisonDesign design;
  design.quantities = {{"eta", "block", false, "/quantities/0", 0.2, 0, "", 0.7}};
  const int trials = 3;
  const ComparisonResult r =
      Compare(scene, lab, design, "e.json", 5, trials, quiet, quiet);
  ASSERT_EQ(r.quantities.size(), 1u);
  const QuantityComparison& q = r.quantities[0];
  EXPECT_FALSE(q.reported);
  EXPECT_TRUE(q.target.from_tracks);
  EXPECT_EQ(LabBasis(q.target, false), "tracks");
  EXPECT_EQ(q.target.label, "eta of block at 0.7 s");
  // The lab: eta = 1 - V at 0.5 s, held at 0.7 s: 0.1, 0.2, 0.6.
  ASSERT_EQ(q.lab.times.size(), 3u);
  EXPECT_NEAR(q.lab.times[0], 0.1, 1e-12);
  EXPECT_NEAR(q.lab.times[1], 0.2, 1e-12);
  EXPECT_NEAR(q.lab.times[2], 0.6, 1e-12);
  EXPECT_NEAR(q.target.lab.value, 0.3, 1e-12);
  EXPECT_NEAR(q.target.lab.variance, 0.07 / 3, 1e-12);  // s^2 = 0.14 / 2

  // The virtual side: each trial's last decision at or before 0.7 s.
  ASSERT_EQ(r.run.records.size(), 3u);
  std::vector<double> want;
  for (const experiment::CycleRecord& c : r.run.records) {
    const sim::TrialResult& trial = c.result.parts.at(0).trial;
    ASSERT_FALSE(trial.trace.empty());
    ASSERT_GE(trial.end_time, 0.7);
    const sim::TraceRow* last = nullptr;
    for (const sim::TraceRow& row : trial.trace)
      if (row.time <= 0.7) last = &row;
    ASSERT_NE(last, nullptr);
    EXPECT_LT(0.7 - last->time, 0.1);
    want.push_back(last->factors.eta);
  }
  EXPECT_EQ(q.virt.times, want);
  ASSERT_TRUE(q.testable) << q.verdict;
  EXPECT_NEAR(q.difference, q.virtual_stat.value - 0.3, 1e-12);

  // The report: a table of its own for eta and lambda_c.
  scene::ExperimentFile file;
  file.file = "e.json";
  file.scene = scene;
  file.input =
      core::ClonePtr<scene::KindInput>(std::make_unique<ComparisonDesign>(design));
  const report::Section section = report::ComparisonSection(file, lab, r, trials);
  EXPECT_NE(section.markdown.find("### Human factors at an instant"), std::string::npos)
      << section.markdown;
  EXPECT_NE(section.markdown.find("| eta of block at 0.7 s | tracks |"),
            std::string::npos)
      << section.markdown;
  EXPECT_EQ(section.summary["quantities"][0]["lab_basis"], "tracks");
  EXPECT_NEAR(section.summary["quantities"][0]["lab_value"].get<double>(), 0.3, 1e-12);
}

}  // namespace
}  // namespace vahf::compare
