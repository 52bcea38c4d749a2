// The precision experiment's statistics on hand-made trial outcomes with known
// answers (report/precision.h): the paired difference and its t interval, the
// KS distance and its equivalent shift, outcome differences, the Monte Carlo
// noise, the rule (each criterion refusing a setting the others pass), and the
// recommendation of the cheapest setting meeting it.
#include "vahf/report/precision.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace vahf::report {
namespace {

using ::testing::HasSubstr;

PartOutcome Completed(double time, double wall = 1.0) {
  PartOutcome o;
  o.reached = true;
  o.status = sim::Status::kCompleted;
  o.completion_time = time;
  o.wall_seconds = wall;
  o.steps = 100;
  o.realizations = 1000;
  return o;
}

PartOutcome Failed(sim::Status status) {
  PartOutcome o;
  o.reached = true;
  o.status = status;
  return o;
}

std::vector<PartOutcome> Completions(const std::vector<double>& times) {
  std::vector<PartOutcome> out;
  for (double t : times) out.push_back(Completed(t));
  return out;
}

const std::vector<double> kReference = {1.0, 1.2, 1.4, 1.6};

// Differences 0.1, 0.05, 0.1, 0.1: mean 0.0875, sd 0.025, standard error
// 0.0125, t(3, 0.975) = 3.182446305: interval 0.0875 -+ 0.039780579.
TEST(ComparePart, PairedDifferenceAndItsInterval) {
  const PartComparison c =
      ComparePart(Completions({1.1, 1.25, 1.5, 1.7}), Completions(kReference), 4);
  EXPECT_EQ(c.cycles, 4u);
  EXPECT_EQ(c.completed, 4u);
  EXPECT_EQ(c.paired, 4u);
  EXPECT_NEAR(*c.difference.mean, 0.0875, 1e-15);
  EXPECT_NEAR(*c.difference.sd, 0.025, 1e-15);
  EXPECT_NEAR(c.difference.ci->lower, 0.0875 - 0.039780579, 1e-9);
  EXPECT_NEAR(c.difference.ci->upper, 0.0875 + 0.039780579, 1e-9);
  EXPECT_NEAR(*c.difference_bound, 0.0875 + 0.039780579, 1e-9);
  EXPECT_NEAR(*c.mean_abs_difference, 0.0875, 1e-15);
  EXPECT_DOUBLE_EQ(*c.p10, 1.145);  // 1.1 + 0.3 (1.25 - 1.1)
  EXPECT_NEAR(*c.reference_p90, 1.54, 1e-15);
  EXPECT_EQ(c.outcome_differences, 0u);
  EXPECT_EQ(*c.steps_median, 100);
}

// The reference's sd over {1.0, 1.2, 1.4, 1.6} is sqrt(0.2/3) = 0.258199; with
// noise_trials = 4 the noise is half of it, 0.129099. The difference bound,
// 0.127281, is just under it; the KS distance 0.25 = 1/4 is what any
// difference at all gives, worth no shift. The rule is met.
TEST(ComparePart, NoiseAndTheRule) {
  const PartComparison c =
      ComparePart(Completions({1.1, 1.25, 1.5, 1.7}), Completions(kReference), 4);
  EXPECT_NEAR(*c.reference_sd, std::sqrt(0.2 / 3), 1e-15);
  EXPECT_NEAR(*c.noise, std::sqrt(0.2 / 3) / 2, 1e-15);
  EXPECT_EQ(c.reference_completed, 4u);
  EXPECT_DOUBLE_EQ(c.ks->distance, 0.25);
  EXPECT_EQ(*c.ks_shift, 0.0);
  EXPECT_DOUBLE_EQ(*c.ks_noise_distance, 0.25);  // 0.129 spans no two of the times
  EXPECT_TRUE(c.meets_rule()) << c.failures;
  // With noise_trials = 5 the noise, 0.115470, is under the bound.
  const PartComparison strict =
      ComparePart(Completions({1.1, 1.25, 1.5, 1.7}), Completions(kReference), 5);
  EXPECT_EQ(strict.failures, "|mean difference| up to 127 ms >= noise 115 ms");
}

// A setting that keeps the mean but loses the spread: every cycle takes
// 0.55 s where the reference's take 0.1, 0.2, ..., 1.0 s. The differences
// 0.45 ... -0.45 have mean 0 and sd 0.302765 (the reference's), so with
// noise_trials = 1 (noise = sd) the bound t(9) sd / sqrt(10) = 0.216585 is
// under the noise; but D = 0.5 needs a shift of 0.4 (five consecutive times
// span 0.4), over the noise: only the KS criterion refuses it.
TEST(ComparePart, TheKsCriterionSeesALostSpread) {
  std::vector<double> reference, setting;
  for (int i = 1; i <= 10; ++i) {
    reference.push_back(0.1 * i);
    setting.push_back(0.55);
  }
  const PartComparison c = ComparePart(Completions(setting), Completions(reference), 1);
  EXPECT_NEAR(*c.noise, 0.302765035409749, 1e-12);
  EXPECT_NEAR(*c.difference.mean, 0.0, 1e-15);
  EXPECT_NEAR(*c.difference_bound, 0.216585, 1e-6);
  EXPECT_DOUBLE_EQ(c.ks->distance, 0.5);
  EXPECT_NEAR(*c.ks_shift, 0.4, 1e-12);
  EXPECT_DOUBLE_EQ(*c.ks_noise_distance, 0.4);  // four times span 0.3 < 0.303
  EXPECT_EQ(c.failures, "KS distance 0.500 (as a shift 400 ms) >= noise 303 ms");
}

// A bimodal time, as the peg's two branches at the chamfer: 90 cycles near
// 0.100 s and 10 at 0.220 s. The setting moves every fast cycle 0.5 ms
// later. The noise (sd about 36 ms over sqrt(12)) dwarfs the mean difference
// (0.45 ms) and the shift that explains D (0.5 ms), but D = 0.9 over 100
// cycles: the KS test tells the two apart (p below 1e-10), and only that
// criterion refuses the setting.
TEST(ComparePart, TheKsTestSeesAShiftedMode) {
  std::vector<double> reference, setting;
  for (int i = 0; i < 100; ++i) {
    const bool slow = i % 10 == 9;
    const double t = slow ? 0.220 : 0.100 + 1e-6 * i;
    reference.push_back(t);
    setting.push_back(slow ? t : t + 5e-4);
  }
  const PartComparison c = ComparePart(Completions(setting), Completions(reference), 12);
  EXPECT_NEAR(*c.difference.mean, 4.5e-4, 1e-12);
  EXPECT_LT(*c.ks_shift, *c.noise);
  EXPECT_LT(*c.difference_bound, *c.noise);
  EXPECT_GE(c.ks->distance, 0.8);
  EXPECT_LT(c.ks->p_value, 1e-10);
  EXPECT_THAT(c.failures, HasSubstr("tells the times from the reference's"));
  EXPECT_EQ(c.failures.find("noise"), std::string::npos) << c.failures;
}

TEST(ComparePart, TheReferenceAgainstItselfHasNoError) {
  const PartComparison c =
      ComparePart(Completions(kReference), Completions(kReference), 12);
  EXPECT_EQ(*c.difference.mean, 0.0);
  EXPECT_EQ(c.difference.ci->lower, 0.0);
  EXPECT_EQ(c.difference.ci->upper, 0.0);
  EXPECT_EQ(*c.difference_bound, 0.0);
  EXPECT_EQ(c.ks->distance, 0.0);
  EXPECT_EQ(*c.ks_shift, 0.0);
  EXPECT_EQ(c.outcome_share, 0.0);
  EXPECT_EQ(*c.p10, *c.reference_p10);
  EXPECT_TRUE(c.meets_rule()) << c.failures;
}

// Cycle 1 times out under the setting, cycle 3 is not reached under the
// reference (an earlier part failed there): 2 of 5 outcomes differ, and the
// statistics of time use the 3 cycles that completed under both.
TEST(ComparePart, OutcomeDifferencesAndPairsOverBothCompleted) {
  std::vector<PartOutcome> setting = Completions({1.0, 0, 1.2, 1.3, 1.4});
  setting[1] = Failed(sim::Status::kTimeout);
  std::vector<PartOutcome> reference = Completions({1.0, 1.1, 1.2, 0, 1.4});
  reference[3] = PartOutcome{};  // not reached
  const PartComparison c = ComparePart(setting, reference, 12);
  EXPECT_EQ(c.cycles, 5u);
  EXPECT_EQ(c.completed, 4u);
  EXPECT_EQ(c.paired, 3u);
  EXPECT_EQ(c.outcome_differences, 2u);
  EXPECT_DOUBLE_EQ(c.outcome_share, 0.4);
  EXPECT_EQ(*c.difference.mean, 0.0);
  EXPECT_EQ(c.reference_completed, 4u);
  EXPECT_THAT(c.failures, HasSubstr("outcome differs in 2/5 cycles (40 % >= 5 %)"));
  EXPECT_EQ(reference[3].StatusText(), "not_reached");
  EXPECT_EQ(setting[1].StatusText(), "timeout");
}

TEST(ComparePart, TooFewPairsOrNoNoise) {
  std::vector<PartOutcome> setting = Completions({1.0, 1.1});
  setting[1] = Failed(sim::Status::kJammed);
  std::vector<PartOutcome> reference = Completions({1.0, 1.1});
  reference[1] = Failed(sim::Status::kJammed);
  const PartComparison c = ComparePart(setting, reference, 12);
  EXPECT_EQ(c.paired, 1u);
  EXPECT_FALSE(c.difference_bound.has_value());
  EXPECT_FALSE(c.noise.has_value());
  EXPECT_THAT(c.failures, HasSubstr("1 cycle(s) completed the part under both: needs 2"));
  EXPECT_THAT(c.failures, HasSubstr("the reference completed the part 1 time(s)"));
}

TEST(SummarizeWall, OverTheTrialsThatReachedThePart) {
  std::vector<PartOutcome> o = {Completed(1, 4.0), Completed(1, 1.0), Completed(1, 2.0),
                                PartOutcome{}};
  const WallSummary w = SummarizeWall(o);
  EXPECT_EQ(w.n, 3u);
  EXPECT_EQ(*w.median, 2.0);
  EXPECT_DOUBLE_EQ(*w.p10, 1.2);
  EXPECT_DOUBLE_EQ(*w.p90, 3.6);
  EXPECT_FALSE(SummarizeWall({PartOutcome{}}).median.has_value());
}

TEST(Recommend, TheCheapestSettingThatMeetsTheRule) {
  const std::vector<Candidate> c = {
      {"reference", 10.0, true, ""},
      {"fast but different", 1.0, false, "outcome differs in 2/20 cycles (10 % >= 5 %)"},
      {"middle", 3.0, false, ""},
      {"adequate", 2.0, false, ""},
      {"slow", 5.0, false, ""},
  };
  const Recommendation r = Recommend(c);
  EXPECT_EQ(r.index, 3u);
  EXPECT_THAT(r.why, HasSubstr("adequate: the cheapest of the 4 of 5 settings"));
  EXPECT_THAT(r.why, HasSubstr("cheaper but refused: fast but different (1 s: outcome "
                               "differs in 2/20 cycles"));
  EXPECT_THAT(r.why, ::testing::Not(HasSubstr("middle")));
}

TEST(Recommend, TheReferenceWhenNoCheaperSettingMeetsTheRule) {
  const std::vector<Candidate> c = {
      {"reference", 10.0, true, ""},
      {"fast", 1.0, false, "|mean difference| up to 5 ms >= noise 1 ms"},
      {"slower than the reference", 12.0, false, ""},
  };
  const Recommendation r = Recommend(c);
  EXPECT_EQ(r.index, 0u);
  EXPECT_THAT(r.why, HasSubstr("no setting cheaper than the reference meets the rule"));
  EXPECT_THAT(r.why, HasSubstr("fast (1 s: |mean difference| up to 5 ms"));
}

TEST(Recommend, TiesGoToTheEarlierSetting) {
  const std::vector<Candidate> c = {{"reference", 10.0, true, ""},
                                    {"first", 2.0, false, ""},
                                    {"second", 2.0, false, ""}};
  EXPECT_EQ(Recommend(c).index, 1u);
}

}  // namespace
}  // namespace vahf::report
