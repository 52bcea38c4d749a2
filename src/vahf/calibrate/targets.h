// What a calibration fits: lab summaries (docs/calibration.md). A target names
// a quantity of one part, over all the lab's trials or one operator's; the lab
// side gives its value and the variance of that value, and the virtual side
// the same statistic over a design that mirrors the lab's operators.
//
//   assembly_time  mean time of the successful trials of the part, s
//                  ("all": of whole cycles); variance s^2 / n
//   success_rate   share of the part's trials that succeeded; variance
//                  p (1 - p) / n with p = (successes + 1) / (n + 2), so that
//                  a rate of 0 or 1 still carries its sampling uncertainty
//                  (the Laplace estimate; Agresti and Coull, Am. Stat. 52(2)
//                  119, 1998, for why the plain p(1 - p) / n fails there)
//   eta, lambda_c  mean of the vision coefficient (Eq. 2) or the comfort
//                  coefficient (Eq. 3) at an instant of the part's trials
//                  (s from the trial's start): on the lab's side from its
//                  sensor tracks (data::FactorsFromTrack, with the curves
//                  the simulation builds for the track's operator), on the
//                  virtual side from each trial's decision trace; the value
//                  of each is its last row at or before the instant
//                  (AddAtInstant, one rule for both sides); variance s^2 / n
//                  as for a time
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/design.h"
#include "vahf/scene/shared_inputs.h"

namespace vahf::calibrate {

inline constexpr const char* kAllParts = "all";

using TargetSpec = scene::FitTarget;

// The quantities a target may name.
const std::vector<std::string>& TargetQuantities();

// A statistic with the variance of its estimate.
struct Statistic {
  double value = 0;
  double variance = 0;  // of `value` as an estimate, in its unit squared
  int n = 0;            // samples behind it
  // A single observation the lab reports without a spread (n = 1, no sd): a
  // draw from the population the virtual side samples, if the model is right,
  // so its variance is the virtual side's per-sample one, n_v * var_v
  // (LabVariance). `variance` is then NaN.
  bool single_draw = false;
};

// The variance of a lab statistic `lab` beside the virtual `virt`: its own,
// or for a single draw the virtual side's per-sample variance.
double LabVariance(const Statistic& lab, const Statistic& virt);

// The samples behind a target: the times of its successful trials (each also
// filed under its operator) and its counts of attempts and successes. For
// eta and lambda_c (scene::AtInstant), `times` holds the factor values at the
// instant, one per track or trial that gave one (attempts = successes = their
// number), and the two counts below the tracks or trials that gave none.
// Operators differ in stature and reach, and both the lab and the virtual
// design hold each operator's share of trials fixed, so the variance of a
// pooled mean time is the stratified one, sum over operators of n_o s_o^2 /
// n^2: the pooled s^2 / n would count the differences between operators,
// which the fixed shares keep out of the mean, as noise (it made the
// intervals 1.5 times too wide on data/synthetic_block). With an operator of
// fewer than two times, s^2 / n.
struct TargetSamples {
  std::vector<double> times;
  std::vector<std::pair<std::string, std::vector<double>>> by_operator;
  int attempts = 0, successes = 0;
  // eta and lambda_c: the factor was NaN at the instant (eta and lambda_c
  // without V, Eqs. 2-3; eta where the part had not yet moved), or the trial
  // was over before the instant or not yet at its first value there.
  int nan_values = 0, no_value = 0;
  void Add(bool success, double time, const std::string& operator_id);
  // The tracks or trials read for eta and lambda_c, with a value or without.
  int Read() const { return attempts + nan_values + no_value; }
  Statistic Of(const std::string& quantity) const;
};

// What one target of a spec covers: one operator's trials ("": all) and one
// repetition's (0: all).
struct TargetScope {
  std::string operator_id;
  int repetition = 0;
};

// The targets a spec makes on a lab: one per operator in order of first
// appearance (by operator), one per repetition the lab's trials record, in
// increasing order (by repetition), else one over all.
std::vector<TargetScope> TargetScopes(const TargetSpec& spec,
                                      const data::LabDataset& lab);

// The lab's samples of a target's part, of one operator ("": all) and one
// repetition (0: all): of its trials, or for eta and lambda_c of its tracks
// (TrackSamples).
TargetSamples LabSamples(const scene::Scene& scene, const data::LabDataset& lab,
                         const TargetSpec& spec, const TargetScope& scope);

// The rule both sides of an eta or lambda_c target share, for one track or
// trial whose rows (sensor samples, decision instants) have strictly
// increasing `times` (s from the trial's start) and factor `values`, and
// which ended at `end`: its value at `instant` is that of the last row at or
// before the instant. The factors are held between rows as the simulation
// holds the operator's decision between decision instants; interpolating
// would blend values across a change of V or of the motion's direction that
// no row measured. Over before the instant (end < instant), or without a row
// at or before it: no value (no_value). A NaN value is left out and counted
// (nan_values).
void AddAtInstant(const std::vector<double>& times, const std::vector<double>& values,
                  double end, double instant, const std::string& operator_id,
                  TargetSamples* samples);

// The lab's eta or lambda_c of a target (of one operator, "": all) from its
// sensor tracks: each track of the target's condition (any when it names
// none) and operator whose trial, the row of trials.csv with the track's
// operator, condition and repetition, is of the target's part, evaluated by
// data::FactorsFromTrack with the curves the simulation builds for that
// operator (experiment::OperatorCondition, sim::OperatorFactorCurves), read
// at the instant by AddAtInstant; a track ends at its last sample. An
// InputError naming the track's file when trials.csv has no trial, or trials
// of several parts, for it: a track's part and its operator's stature and arm
// length (r's breakpoints, Fig. 4) come from its trial.
TargetSamples TrackSamples(const scene::Scene& scene, const data::LabDataset& lab,
                           const TargetSpec& spec, const TargetScope& scope);

// One residual of a calibration: the lab's statistic for a target (for one
// operator, or "" for all).
struct Target {
  TargetSpec spec;
  std::string operator_id;  // "" for all operators
  int repetition = 0;       // > 0: of this repetition only (by repetition)
  std::string label;        // "assembly_time of peg, operator male 1"
  std::string unit;         // "s" or "1"
  Statistic lab;
  // eta, lambda_c: the lab's statistic is from its sensor tracks, measured
  // with the scene's factor curves (a fit of those curves would move it).
  bool from_tracks = false;
};

// For the targets of each spec with pooled_variance (one per operator), the
// variance of each operator's mean from the spec's pooled within-operator
// variance: s_p^2 = sum_o (n_o - 1) s_o^2 / sum_o (n_o - 1), the error mean
// square of a one-way analysis of variance (Montgomery, Design and Analysis
// of Experiments, 9th ed., 2017, Sec. 3.3), and operator o's variance
// s_p^2 / n_o. `stats` is one per target (the lab's or the virtual side's);
// a statistic without a finite variance adds nothing to s_p^2 and, with
// n >= 1 and not a single draw, takes s_p^2 / n. Why: an operator's own s_o^2 from 6
// trials has 5 degrees of freedom, and the residual it whitens is then t-distributed with
// about 11, not normal: the intervals come out about 10 % too narrow
// (docs/calibration.md, "Pooled variances"). Pooling over 8 operators gives 40.
void PoolVariances(const std::vector<Target>& targets, std::vector<Statistic>* stats);

// The lab's operators in order of first appearance in its trials.
std::vector<std::string> LabOperators(const data::LabDataset& lab);
// The repetitions its trials record, increasing, each once.
std::vector<int> LabRepetitions(const data::LabDataset& lab);

// A target of `spec` over `scope` with its label and unit; its lab statistic
// is left for the caller.
Target MakeTarget(const TargetSpec& spec, const TargetScope& scope);

// What a reported value without sd and n or an uncertainty gives: an
// InputError (a calibration cannot weigh it), or its point alone with a NaN
// variance (a comparison shows it and calls it untestable).
enum class Unweighted { kRefuse, kPoint };

// The lab's targets, in spec order and, by operator, in the order operators
// first appear in the lab's trials. A target's lab statistic comes from the
// lab's trials of its part (and condition; a target without one pools every
// condition's trials); without any, from what the lab reports: a segment's
// counts (segments.csv) or a summary (summaries.csv), weighted by its sd and
// n or its reading uncertainty (without either: see Unweighted). A reported
// row answers a target of its quantity, part and segment whose condition is
// the row's; a target without a condition takes the row without one, else
// the only condition the lab reports it for (an InputError when there are
// several: the target must name one; for eta and lambda_c, the row of the
// target's instant). eta and lambda_c come from the lab's tracks
// (TrackSamples), and from what it reports only when it has no track for
// the target. An InputError naming `experiment_file` and the target's
// pointer when the lab has no trials (tracks) for it (or, for assembly_time,
// eta and lambda_c, fewer than two values: no variance). A spec with
// pooled_variance has its operators' variances pooled (PoolVariances).
std::vector<Target> LabTargets(const scene::Scene& scene, const data::LabDataset& lab,
                               const std::vector<TargetSpec>& specs,
                               const std::string& experiment_file,
                               Unweighted unweighted = Unweighted::kRefuse);

// The virtual design that mirrors the lab: one condition per lab operator (by
// first appearance in its trials), the scene with the operator's sex, stature
// and arm length (experiment::OperatorCondition); the scene's own operator
// when the lab has no trials. An InputError naming the lab's trials file and
// row when an operator's stature and arm length break the scene's reach rule
// (D1 < D2 < D3). Operator k draws from cycle indices k * trials,
// k * trials + 1, ...: lab operators are different people, whose errors are
// independent, and so must the virtual ones' be for the targets of different
// operators to be independent residuals (with shared streams the six
// operators of data/synthetic_block gave a standard error 2.5 times too small).
// Each operator repeats the task as the lab's operators did: cycle j is
// repetition (j mod R) + 1, R the largest repetition of the lab's trials
// (experiment::Condition::repetitions), so a learning model (human/learning.h)
// practises the virtual operators as the lab's were. With a learning model,
// `trials` must be a multiple of R, every repetition run equally often (an
// InputError naming the lab's trials file otherwise).
std::vector<experiment::Condition> LabConditions(const scene::Scene& scene,
                                                 const data::LabDataset& lab, int trials);

// Empty when the scene's reach parameters give every lab operator
// D1 < D2 < D3; else the first operator they fail, with the rule's numbers.
std::string LabReachViolation(const scene::Scene& scene, const data::LabDataset& lab);

// A target's statistic on a run of LabConditions. A part trial that ended
// as a numerical failure is left out (it says nothing about the assembly).
// With no sample (no completed trial for assembly_time), value is NaN.
// eta and lambda_c come from each part trial's decision trace (recorded:
// experiment::RunDesign's record_trace), read at the instant by AddAtInstant;
// for part "all", the cycle's trials on one clock from its start.
// A segment target reads the conditions whose 0-based segment, in
// `segments` (experiment::FatigueRun::segments), is its own.
Statistic VirtualStatistic(const Target& target, const experiment::DesignRun& run,
                           const std::vector<int>& segments = {});
// The samples VirtualStatistic summarises.
TargetSamples VirtualSamples(const Target& target, const experiment::DesignRun& run,
                             const std::vector<int>& segments = {});

}  // namespace vahf::calibrate
