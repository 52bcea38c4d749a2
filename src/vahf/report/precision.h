// The statistics of the precision experiment (docs/experiments.md,
// "precision"): one part's trials under a setting against the same cycles
// under the reference, the Monte Carlo noise the setting's error must stay
// under, and the rule that recommends a setting. Pure functions of the trial
// outcomes, so they are tested on hand-made records; precision_section.cc
// turns them into tables, summary.json, measured.json, report.md and plots.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vahf/sim/trial_result.h"
#include "vahf/stats/distribution.h"
#include "vahf/stats/summary.h"

namespace vahf::report {

// The share of cycles whose outcome may differ from the reference's: at or
// above it a setting changes what experiments count (success rates).
inline constexpr double kMaxOutcomeShare = 0.05;

// The level of the KS test of the rule: a setting whose completion times the
// two-sample KS test tells from the reference's at this level (p below it)
// changes the distribution detectably, however small the shift that would
// explain D. At 200 cycles it is D < 0.136 (1.36 sqrt(2 / 200)).
// With common random numbers the two samples are positively correlated,
// which makes the test conservative (it rejects less often than its level).
inline constexpr double kKsLevel = 0.05;

// One part in one cycle under one setting.
struct PartOutcome {
  bool reached = false;  // an earlier part of the cycle failed: not attempted
  sim::Status status = sim::Status::kTimeout;  // if reached
  double completion_time = 0;                  // s from the part's start, if completed
  double wall_seconds = 0;                     // measured, if reached
  std::int64_t steps = 0;                      // integrator steps taken, if reached
  std::int64_t realizations = 0;               // if reached

  bool completed() const { return reached && status == sim::Status::kCompleted; }
  // StatusName, or "not_reached".
  std::string StatusText() const;
};

// A setting against the reference for one part, over the same cycles (cycle j
// of each vector under the same streams). Only deterministic quantities: no
// wall time.
struct PartComparison {
  std::size_t cycles = 0;
  std::size_t completed = 0;  // cycles in which the setting completed the part
  std::size_t paired = 0;     // ... and the reference did too
  stats::Summary difference;  // completion time, setting - reference, paired, s
  // max(|lower|, |upper|) of the difference's 95 % t interval: how large the
  // mean difference may be; empty for fewer than 2 pairs.
  std::optional<double> difference_bound;
  std::optional<double> mean_abs_difference;  // s, paired
  // Two-sample KS between the paired completion times of each (distribution.h).
  std::optional<stats::KolmogorovSmirnov> ks;
  // KsEquivalentShift of D on the reference's paired times: the smallest shift
  // of them that gives a KS distance as large, s.
  std::optional<double> ks_shift;
  // KsDistanceOfShift of those times by the noise: the KS distance a shift by
  // the noise gives (ks_shift < noise exactly when D reaches no further).
  std::optional<double> ks_noise_distance;
  std::optional<double> p10, p90, reference_p10, reference_p90;  // paired, s
  std::size_t outcome_differences = 0;  // cycles whose status (or reaching) differs
  double outcome_share = 0;             // outcome_differences / cycles
  std::optional<double> steps_median, realizations_median;  // over reached trials

  // The reference's completion times (all its completions) and the Monte
  // Carlo noise of an experiment of noise_trials cycles: sd / sqrt(noise_trials).
  std::size_t reference_completed = 0;
  std::optional<double> reference_sd, noise;

  // The rule for this part (MeetsRule): empty when met, else every reason not.
  std::string failures;
  bool meets_rule() const { return failures.empty(); }
};

// `setting` and `reference` hold the same cycles in the same order.
PartComparison ComparePart(const std::vector<PartOutcome>& setting,
                           const std::vector<PartOutcome>& reference, int noise_trials);

// The rule, for one part: at least 2 paired completions, a reference noise,
// difference_bound < noise, ks_shift < noise, the KS p-value at least
// kKsLevel and outcome_share < kMaxOutcomeShare. Returns the reasons it is not met, ";
// "-separated, times in ms ("" when met).
std::string RuleFailures(const PartComparison& c);

// Wall time of a setting's trials of one part: median, p10, p90 (s); empty
// when no trial reached the part.
struct WallSummary {
  std::size_t n = 0;
  std::optional<double> median, p10, p90;
};
WallSummary SummarizeWall(const std::vector<PartOutcome>& outcomes);

// A setting of one scene as the recommendation sees it.
struct Candidate {
  std::string label;
  double cost = 0;         // median wall seconds per cycle (all its parts)
  bool reference = false;  // meets the rule by definition
  std::string failures;    // "" when every part meets the rule, else which did not
};

struct Recommendation {
  std::size_t index = 0;  // into the candidates
  std::string why;
};

// The cheapest candidate that meets the rule (the reference always does);
// ties go to the earlier one. `why` names its cost, how many met the rule,
// and each cheaper candidate with the reason it was refused. At least one
// candidate must be the reference.
Recommendation Recommend(const std::vector<Candidate>& candidates);

}  // namespace vahf::report
