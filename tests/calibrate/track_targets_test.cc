// eta (Eq. 2) and lambda_c (Eq. 3) targets at an instant: the lab's side
// from sensor tracks whose factors follow by hand (the geometry of
// tests/data/track_factors_test.cc, with the default curves of
// docs/parameters.md), the virtual side from hand-made decision traces, the
// one rule both share (the last row at or before the instant), and the
// experiment file's `instant`.
//
//   f: 0.5 at 0 deg, 1 on [30, 45] deg, 0 at 180 deg   (Fig. 3)
//   g: 0.5 at 0 deg, 1 on [30, 90] deg, 0 at 180 deg   (Fig. 5)
//   r: 1 to D1 = 0.85 l, 0.5 at D2 = 0.39 h, 0 at D3 = 0.68 h (Fig. 4)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/quiet_runner.h"
#include "support/standing_operator.h"
#include "vahf/calibrate/calibration.h"
#include "vahf/calibrate/targets.h"
#include "vahf/core/error.h"
#include "vahf/human/factor_curves.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {
namespace {

using Eigen::Vector3d;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string Path(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

// The block scene, with the default curves the numbers below assume.
scene::Scene Block() {
  const scene::Scene s =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const human::ReachCurve reach;
  EXPECT_EQ(s.params.reach.d1_arm_fraction, reach.d1_arm_fraction);
  EXPECT_EQ(s.params.reach.d2_height_fraction, reach.d2_height_fraction);
  EXPECT_EQ(s.params.reach.d3_height_fraction, reach.d3_height_fraction);
  EXPECT_EQ(s.params.reach.value_at_d2, reach.value_at_d2);
  return s;
}

// Operator "short" (l = 0.74 m, h = 1.75 m): D1 = 0.629, D2 = 0.6825 m.
// Operator "long" (l = 0.80 m, h = 1.80 m): D1 = 0.68, D2 = 0.702 m.
double ReachShort(double d) {
  const double d1 = 0.85 * 0.74, d2 = 0.39 * 1.75;
  return 1.0 - 0.5 * (d - d1) / (d2 - d1);
}

// The part is lowered 0.4 m by t = 0.5 s, held, then drawn 0.4 m in by
// t = 1.5 s; V at the samples 1-3 as given. By hand (track_factors_test):
//   t = 0.5  f = 1, g = 1, shoulder sqrt(0.45) m: eta = 1 - V, lambda_c =
//            1 - (r + 1) / 2 V with r = ReachShort(sqrt(0.45)) = 0.6092 for
//            "short", r = 1 for "long" (sqrt(0.45) = 0.6708 < D1 = 0.68)
//   t = 1.0  the same posture and part, the direction carried on
//   t = 1.5  f = 2/3, g = 0.5, r = 1: eta = 1 - 2/3 V, lambda_c = 1 - 0.75 V
data::SensorTrack HandTrack(const std::string& op, int repetition, double v1, double v2,
                            double v3) {
  data::SensorTrack t;
  t.file = "tracks/" + op + "_" + std::to_string(repetition) + ".csv";
  t.operator_id = op;
  t.condition = "good";
  t.repetition = repetition;
  // The operator stands still (support/standing_operator.h, the geometry of
  // tests/data/track_factors_test.cc).
  t.samples = {testing::StandingSample(2, 0.0, {0, 0, 0.4}, 1.0),
               testing::StandingSample(3, 0.5, {0, 0, 0}, v1),
               testing::StandingSample(4, 1.0, {0, 0, 0}, v2),
               testing::StandingSample(5, 1.5, {-0.4, 0, 0}, v3)};
  return t;
}

data::LabTrial Trial(const std::string& op, int repetition, const std::string& part,
                     int line) {
  data::LabTrial t;
  t.operator_id = op;
  t.sex = "male";
  t.height = op == "long" ? 1.80 : 1.75;
  t.arm_length = op == "long" ? 0.80 : 0.74;
  t.condition = "good";
  t.part = part;
  t.repetition = repetition;
  t.time = 2.0;
  t.success = 1;
  t.line = line;
  return t;
}

// Two tracks of "short" (repetitions 1, 2) and one of "long" (1), each of a
// trial of the block.
data::LabDataset Lab() {
  data::LabDataset lab;
  lab.file = "lab/dataset.json";
  lab.trials_file = "trials.csv";
  lab.trials = {Trial("short", 1, "block", 2), Trial("short", 2, "block", 3),
                Trial("long", 1, "block", 4)};
  lab.tracks = {HandTrack("short", 1, 0.5, kNaN, 0.8),
                HandTrack("short", 2, 1.0, 0.9, 0.6),
                HandTrack("long", 1, 0.4, 0.4, 0.3)};
  return lab;
}

TargetSpec Spec(const std::string& quantity, double instant, bool by_operator = false) {
  TargetSpec s;
  s.quantity = quantity;
  s.part = "block";
  s.by_operator = by_operator;
  s.pointer = "/targets/0";
  s.condition = "good";
  s.instant = instant;
  return s;
}

// Mean and s^2 / n by hand.
void ExpectMean(const Statistic& s, const std::vector<double>& x) {
  double m = 0, ss = 0;
  for (double v : x) m += v / static_cast<double>(x.size());
  for (double v : x) ss += (v - m) * (v - m);
  const double n = static_cast<double>(x.size());
  EXPECT_EQ(s.n, static_cast<int>(x.size()));
  EXPECT_NEAR(s.value, m, 1e-12);
  EXPECT_NEAR(s.variance, ss / (n - 1) / n, 1e-12);
}

// At a sample, the sample's eta: 1 - V at t = 0.5 for each track.
TEST(TrackTargets, EtaAtASampleByHand) {
  const scene::Scene scene = Block();
  const data::LabDataset lab = Lab();
  const TargetSamples s = TrackSamples(scene, lab, Spec("eta", 0.5), {});
  EXPECT_EQ(s.nan_values, 0);
  EXPECT_EQ(s.no_value, 0);
  ASSERT_EQ(s.times.size(), 3u);
  EXPECT_NEAR(s.times[0], 0.5, 1e-12);
  EXPECT_NEAR(s.times[1], 0.0, 1e-12);
  EXPECT_NEAR(s.times[2], 0.6, 1e-12);
  const std::vector<Target> t = LabTargets(scene, lab, {Spec("eta", 0.5)}, "e.json");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_TRUE(t[0].from_tracks);
  EXPECT_EQ(t[0].label, "eta of block at 0.5 s, good");
  EXPECT_EQ(t[0].unit, "1");
  ExpectMean(t[0].lab, {0.5, 0.0, 0.6});

  // t = 1.5: eta = 1 - 2/3 V.
  ExpectMean(LabTargets(scene, lab, {Spec("eta", 1.5)}, "e.json")[0].lab,
             {1 - 0.8 * 2 / 3.0, 1 - 0.6 * 2 / 3.0, 1 - 0.3 * 2 / 3.0});
}

// lambda_c with the curves of each track's own operator: r at sqrt(0.45) m is
// 0.6092 for "short" but 1 for "long", whose D1 lies beyond it. With the
// scene's own operator's curves (l = 0.72 m, h = 1.70 m: D2 = 0.663 m, so r =
// 0.49 there) every value would differ.
TEST(TrackTargets, LambdaUsesEachOperatorsCurves) {
  const scene::Scene scene = Block();
  const data::LabDataset lab = Lab();
  const double r = ReachShort(std::sqrt(0.45));
  EXPECT_NEAR(r, 0.60916, 1e-5);
  const TargetSpec spec = Spec("lambda_c", 0.5, true);
  ExpectMean(TrackSamples(scene, lab, spec, {"short"}).Of("lambda_c"),
             {1 - (r + 1) / 2 * 0.5, 1 - (r + 1) / 2 * 1.0});
  const TargetSamples only = TrackSamples(scene, lab, spec, {"long"});
  ASSERT_EQ(only.times.size(), 1u);
  EXPECT_NEAR(only.times[0], 1 - 1.0 * 0.4, 1e-12);
  // By operator, "long" has one value: no variance, an InputError.
  try {
    LabTargets(scene, lab, {spec}, "e.json");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/targets/0");
    EXPECT_NE(e.rule().find("(operator long) has 1 value(s) of lambda_c at 0.5 s"),
              std::string::npos)
        << e.rule();
  }
}

// Between samples the value is the last sample's, not an interpolation: at
// 0.75 s that of 0.5 s (interpolating towards 1.0 s would give "short" 2
// 0.05 instead of 0, and "short" 1, whose 1.0 s has no V, NaN); at 1.2 s
// that of 1.0 s, where "short" 1 has no V (eta NaN: left out and counted),
// "short" 2 has V = 0.9 and "long" V = 0.4.
TEST(TrackTargets, BetweenSamplesTheLastAtOrBefore) {
  const scene::Scene scene = Block();
  const data::LabDataset lab = Lab();
  const TargetSamples at = TrackSamples(scene, lab, Spec("eta", 0.5), {});
  const TargetSamples between = TrackSamples(scene, lab, Spec("eta", 0.75), {});
  EXPECT_EQ(between.times, at.times);
  const TargetSamples later = TrackSamples(scene, lab, Spec("eta", 1.2), {});
  EXPECT_EQ(later.nan_values, 1);
  ASSERT_EQ(later.times.size(), 2u);
  EXPECT_NEAR(later.times[0], 1 - 0.9, 1e-12);
  EXPECT_NEAR(later.times[1], 1 - 0.4, 1e-12);
  // Just before the next sample, still the last one's.
  EXPECT_EQ(TrackSamples(scene, lab, Spec("eta", 1.4999), {}).times, later.times);
}

// A track that ends before the instant contributes nothing; so does one not
// yet at its first value (sample 0 has no motion: no factors before t_1).
TEST(TrackTargets, ATrackOverBeforeTheInstantGivesNothing) {
  const scene::Scene scene = Block();
  data::LabDataset lab = Lab();
  lab.tracks[2].samples.pop_back();  // "long" ends at 1.0 s
  const TargetSamples s = TrackSamples(scene, lab, Spec("eta", 1.5), {});
  EXPECT_EQ(s.no_value, 1);
  ASSERT_EQ(s.times.size(), 2u);
  ExpectMean(LabTargets(scene, lab, {Spec("eta", 1.5)}, "e.json")[0].lab,
             {1 - 0.8 * 2 / 3.0, 1 - 0.6 * 2 / 3.0});
  // At its last sample it still counts.
  EXPECT_EQ(TrackSamples(scene, lab, Spec("eta", 1.0), {}).Read(), 3);
  EXPECT_EQ(TrackSamples(scene, lab, Spec("eta", 1.0), {}).no_value, 0);
  const TargetSamples early = TrackSamples(scene, lab, Spec("eta", 0.2), {});
  EXPECT_EQ(early.no_value, 3);
  EXPECT_TRUE(early.times.empty());
  // Every track over: fewer than two values, an InputError for a calibration.
  try {
    LabTargets(scene, lab, {Spec("eta", 2.0)}, "e.json");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "e.json");
    EXPECT_EQ(e.where(), "/targets/0");
    EXPECT_NE(e.rule().find("0 value(s) of eta at 2 s from its 3 track(s)"),
              std::string::npos)
        << e.rule();
    EXPECT_NE(e.rule().find("3 over before the instant"), std::string::npos) << e.rule();
  }
}

// Which tracks a target reads: its condition, its operator, and its part
// through the track's trial in trials.csv.
TEST(TrackTargets, TracksOfTheTargetsPartAndCondition) {
  const scene::Scene scene = Block();
  data::LabDataset lab = Lab();
  lab.trials[1].part = "all";  // "short" 2 is of the whole assembly
  lab.tracks[2].condition = "poor";
  lab.trials[2].condition = "poor";
  const TargetSamples s = TrackSamples(scene, lab, Spec("eta", 0.5), {});
  ASSERT_EQ(s.times.size(), 1u);
  EXPECT_NEAR(s.times[0], 0.5, 1e-12);
  TargetSpec all = Spec("eta", 0.5);
  all.part = kAllParts;
  EXPECT_EQ(TrackSamples(scene, lab, all, {}).times, std::vector<double>{0.0});
  TargetSpec any = Spec("eta", 0.5);
  any.condition.clear();  // every condition's
  EXPECT_EQ(TrackSamples(scene, lab, any, {}).times.size(), 2u);
}

TEST(TrackTargets, ATrackWithoutItsTrialIsAnInputError) {
  const scene::Scene scene = Block();
  data::LabDataset lab = Lab();
  lab.trials.pop_back();  // "long" 1
  try {
    TrackSamples(scene, lab, Spec("eta", 0.5), {});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "tracks/long_1.csv");
    EXPECT_EQ(e.where(), "operator 'long', condition 'good', repetition 1");
    EXPECT_NE(e.rule().find("trials.csv has no trial"), std::string::npos) << e.rule();
  }
  lab = Lab();
  lab.trials.push_back(Trial("long", 1, "all", 9));
  try {
    TrackSamples(scene, lab, Spec("eta", 0.5), {});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "tracks/long_1.csv");
    EXPECT_NE(e.rule().find("parts 'block' (line 4) and 'all' (line 9)"),
              std::string::npos)
        << e.rule();
  }
}

// Without tracks for the target, what the lab reports at the target's
// instant (summaries.csv), and nothing at another instant.
TEST(TrackTargets, WithoutTracksTheSummaryAtTheInstant) {
  const scene::Scene scene = Block();
  data::LabDataset lab = Lab();
  lab.tracks.clear();
  lab.summaries_file = "summaries.csv";
  data::LabSummary row;
  row.quantity = "eta";
  row.part = "block";
  row.condition = "good";
  row.instant = 3.0;
  row.value = 0.3;
  row.sd = 0.1;
  row.n = 4;
  row.line = 2;
  data::LabSummary other = row;
  other.instant = 6.0;
  other.value = 0.7;
  lab.summaries = {other, row};
  const Target t = LabTargets(scene, lab, {Spec("eta", 3.0)}, "e.json")[0];
  EXPECT_FALSE(t.from_tracks);
  EXPECT_DOUBLE_EQ(t.lab.value, 0.3);
  EXPECT_NEAR(t.lab.variance, 0.01 / 4, 1e-15);
  try {
    LabTargets(scene, lab, {Spec("eta", 4.0)}, "e.json");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.rule().find("no sensor tracks of this part in condition 'good' and "
                            "reports no eta at 4 s"),
              std::string::npos)
        << e.rule();
  }
}

// --------------------------------------------------------------- virtual side

sim::TraceRow Row(double time, double eta, double lambda) {
  sim::TraceRow row;
  row.time = time;
  row.factors.eta = eta;
  row.factors.lambda_c = lambda;
  return row;
}

experiment::PartRun Part(const std::string& name, double start, double end,
                         std::vector<sim::TraceRow> trace,
                         sim::Status status = sim::Status::kCompleted) {
  experiment::PartRun p;
  p.start_time = start;
  p.trial.part = name;
  p.trial.status = status;
  p.trial.end_time = end;
  p.trial.completion_time = end;
  p.trial.trace = std::move(trace);
  return p;
}

// Cycles of two parts, "block" then "lid", decisions every 0.1 s.
experiment::DesignRun HandRun() {
  experiment::DesignRun run;
  run.conditions = {{"short", "male", nullptr}, {"long", "male", nullptr}};
  const auto cycle = [](std::size_t condition, std::vector<experiment::PartRun> parts) {
    experiment::CycleRecord r;
    r.condition = condition;
    r.result.parts = std::move(parts);
    return r;
  };
  run.records = {
      cycle(0, {Part("block", 0, 0.25,
                     {Row(0, 0.1, 0.5), Row(0.1, 0.2, 0.6), Row(0.2, 0.3, 0.7)}),
                Part("lid", 0.25, 0.5, {Row(0, 0.9, 0.1), Row(0.1, 0.8, 0.2)})}),
      // Over at 0.15 s (timed out): no value after it.
      cycle(0, {Part("block", 0, 0.15, {Row(0, 0.4, 0.5), Row(0.1, kNaN, 0.4)},
                     sim::Status::kTimeout)}),
      // A failure of the computation says nothing.
      cycle(1, {Part("block", 0, 0.3, {Row(0, 0.5, 0.5), Row(0.1, 0.5, 0.5)},
                     sim::Status::kNumericalFailure)}),
      cycle(1, {Part("block", 0, 0.3,
                     {Row(0, 0.6, 0.5), Row(0.1, 0.7, 0.3), Row(0.2, 0.75, 0.2)})})};
  return run;
}

Target Virtual(const std::string& quantity, double instant, const std::string& part,
               const std::string& op = "") {
  TargetSpec spec = Spec(quantity, instant);
  spec.part = part;
  return MakeTarget(spec, {op});
}

TEST(TrackTargets, VirtualSideTheLastDecisionAtOrBefore) {
  const experiment::DesignRun run = HandRun();
  // At 0.1 s: 0.2, NaN (left out), 0.7; the failed computation not at all.
  TargetSamples s = VirtualSamples(Virtual("eta", 0.1, "block"), run);
  EXPECT_EQ(s.times, (std::vector<double>{0.2, 0.7}));
  EXPECT_EQ(s.nan_values, 1);
  EXPECT_EQ(s.Read(), 3);
  // Between decisions, the last one's: 0.15 is within the timed-out trial.
  s = VirtualSamples(Virtual("eta", 0.15, "block"), run);
  EXPECT_EQ(s.times, (std::vector<double>{0.2, 0.7}));
  // At 0.2 s the timed-out trial is over: no value.
  s = VirtualSamples(Virtual("lambda_c", 0.2, "block"), run);
  EXPECT_EQ(s.times, (std::vector<double>{0.7, 0.2}));
  EXPECT_EQ(s.no_value, 1);
  ExpectMean(VirtualStatistic(Virtual("lambda_c", 0.2, "block"), run), {0.7, 0.2});
  // One operator's trials.
  s = VirtualSamples(Virtual("eta", 0.2, "block", "long"), run);
  EXPECT_EQ(s.times, std::vector<double>{0.75});
  // The lid's own clock starts with its trial.
  s = VirtualSamples(Virtual("eta", 0.1, "lid"), run);
  EXPECT_EQ(s.times, std::vector<double>{0.8});
}

// For "all", the cycle's clock: the lid's rows at 0.25 + its times.
TEST(TrackTargets, VirtualSideOfWholeCyclesOnTheCyclesClock) {
  const experiment::DesignRun run = HandRun();
  TargetSamples s = VirtualSamples(Virtual("eta", 0.3, kAllParts), run);
  // Cycle 1: the block's 0.3 until 0.25, then the lid's first row, 0.9.
  // Cycle 2: over at 0.15. Cycle 4: over at 0.3, its last row 0.75.
  EXPECT_EQ(s.times, (std::vector<double>{0.9, 0.75}));
  EXPECT_EQ(s.no_value, 1);
  s = VirtualSamples(Virtual("eta", 0.24, kAllParts), run);
  EXPECT_EQ(s.times, (std::vector<double>{0.3, 0.75}));
}

// The rule itself, as both sides call it.
TEST(TrackTargets, AddAtInstant) {
  TargetSamples s;
  const std::vector<double> t = {0.5, 1.0, 1.5}, v = {0.1, kNaN, 0.3};
  AddAtInstant(t, v, 1.5, 0.5, "a", &s);   // at a row
  AddAtInstant(t, v, 1.5, 1.49, "a", &s);  // between: the earlier, NaN
  AddAtInstant(t, v, 1.5, 1.5, "a", &s);   // at the end
  AddAtInstant(t, v, 1.5, 1.6, "a", &s);   // over
  AddAtInstant(t, v, 1.5, 0.4, "a", &s);   // before the first row
  EXPECT_EQ(s.times, (std::vector<double>{0.1, 0.3}));
  EXPECT_EQ(s.nan_values, 1);
  EXPECT_EQ(s.no_value, 2);
  // A trial over before its last row's time cannot be, but an end between
  // rows is: the last row stands until the end.
  TargetSamples e;
  AddAtInstant({0.0, 0.1}, {0.4, 0.5}, 0.15, 0.15, "a", &e);
  EXPECT_EQ(e.times, std::vector<double>{0.5});
}

// --------------------------------------------------------------- calibrate

experiment::RunnerOptions Quiet() { return testing::QuietRunner(); }

CalibrationSpec FitTo(const std::string& parameter, double start, double lower,
                      double upper, const TargetSpec& target) {
  CalibrationSpec spec;
  spec.max_iterations = 3;
  spec.stages.emplace_back();
  spec.stages[0].parameters = {{parameter, start, lower, upper, "/parameters/0", ""}};
  spec.stages[0].targets = {target};
  return spec;
}

// An eta target from tracks is a target like any other: the fit runs the
// lab's operators with their decision traces, and reports the tracks' value.
TEST(TrackTargets, ACalibrationFitsToEtaFromTracks) {
  const scene::Scene scene = Block();
  const data::LabDataset lab = Lab();
  const CalibrationSpec spec =
      FitTo("guidance/kappa", 400.0, 100.0, 1000.0, Spec("eta", 0.7));
  const CalibrationResult r =
      CalibrateStage(scene, lab, spec, spec.stages[0], "e.json", 3, 3, Quiet());
  ASSERT_EQ(r.targets.size(), 1u);
  EXPECT_TRUE(r.targets[0].target.from_tracks);
  ExpectMean(r.targets[0].target.lab, {0.5, 0.0, 0.6});  // eta = 1 - V at 0.5 s
  EXPECT_EQ(r.targets[0].start.n, 6);  // 3 cycles of each of the 2 operators
  EXPECT_TRUE(std::isfinite(r.targets[0].fitted.value));
}

// The tracks are measured with the scene's curves: fitting one of them would
// move the lab's value with the virtual one.
TEST(TrackTargets, ACurveCannotBeFittedToTrackTargets) {
  const scene::Scene scene = Block();
  const CalibrationSpec spec =
      FitTo("reach/d1_arm_fraction", 0.85, 0.7, 0.95, Spec("lambda_c", 0.5));
  try {
    CalibrateStage(scene, Lab(), spec, spec.stages[0], "e.json", 3, 3, Quiet());
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "e.json");
    EXPECT_EQ(e.where(), "/parameters/0/name");
    EXPECT_EQ(e.value(), "reach/d1_arm_fraction");
    EXPECT_NE(e.rule().find("lambda_c of block at 0.5 s, good"), std::string::npos)
        << e.rule();
  }
}

// ------------------------------------------------------- the experiment file

std::vector<scene::FitTarget> Read(const nlohmann::json& targets, bool margin = false) {
  return scene::ReadTargets(scene::JsonNode(targets, "e.json", "/targets"), Block(),
                            margin);
}

void ExpectReadError(const nlohmann::json& targets, const std::string& where,
                     const std::string& value, const std::string& rule) {
  try {
    Read(targets);
    ADD_FAILURE() << "no InputError; expected one at " << where;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "e.json");
    EXPECT_EQ(e.where(), where);
    EXPECT_EQ(e.value(), value);
    EXPECT_NE(e.rule().find(rule), std::string::npos) << e.rule();
  }
}

TEST(TrackTargets, TheInstantInTheExperimentFile) {
  using nlohmann::json;
  const std::vector<scene::FitTarget> t =
      Read(json::array({{{"quantity", "eta"}, {"part", "block"}, {"instant", 3}},
                        {{"quantity", "lambda_c"}, {"part", "all"}, {"instant", 0}},
                        {{"quantity", "assembly_time"}, {"part", "block"}}}));
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].quantity, "eta");
  EXPECT_DOUBLE_EQ(t[0].instant, 3.0);
  EXPECT_EQ(t[1].quantity, "lambda_c");
  EXPECT_DOUBLE_EQ(t[1].instant, 0.0);
  EXPECT_TRUE(std::isnan(t[2].instant));
  EXPECT_EQ(TargetQuantities(), (std::vector<std::string>{"assembly_time", "success_rate",
                                                          "eta", "lambda_c"}));

  ExpectReadError(
      json::array({{{"quantity", "eta"}, {"part", "block"}, {"instant", -1}}}),
      "/targets/0/instant", "-1", "must be >= 0");
  ExpectReadError(
      json::array({{{"quantity", "eta"}, {"part", "block"}, {"instant", kNaN}}}),
      "/targets/0/instant", "nan", "must be a finite number");
  ExpectReadError(
      json::array({{{"quantity", "eta"}, {"part", "block"}, {"instant", "3 s"}}}),
      "/targets/0/instant", "\"3 s\"", "must be a number");
  ExpectReadError(json::array({{{"quantity", "lambda_c"}, {"part", "block"}}}),
                  "/targets/0/instant", "(missing)", "required");
  ExpectReadError(
      json::array({{{"quantity", "success_rate"}, {"part", "block"}, {"instant", 3}}}),
      "/targets/0/instant", "3", "only eta and lambda_c are read at an instant");
  ExpectReadError(
      json::array(
          {{{"quantity", "eta"}, {"part", "block"}, {"instant", 3}, {"segment", 1}}}),
      "/targets/0/segment", "1", "not from a segment");
}

}  // namespace
}  // namespace vahf::calibrate
