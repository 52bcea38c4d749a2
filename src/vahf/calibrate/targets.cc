#include "vahf/calibrate/targets.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

#include "vahf/core/error.h"
#include "vahf/data/track_factors.h"
#include "vahf/sim/trial_model.h"
#include "vahf/stats/summary.h"

namespace vahf::calibrate {
namespace {

const char* UnitOf(const std::string& quantity) {
  return quantity == "assembly_time" ? "s" : "1";
}

// The operators of the lab's trials in order of first appearance.
std::vector<const data::LabTrial*> FirstTrialOfEachOperator(const data::LabDataset& lab) {
  std::vector<const data::LabTrial*> out;
  for (const data::LabTrial& t : lab.trials)
    if (std::none_of(out.begin(), out.end(), [&](const data::LabTrial* o) {
          return o->operator_id == t.operator_id;
        }))
      out.push_back(&t);
  return out;
}

// Whether a trial or track of `repetition` is in the scope.
bool OfRepetition(const TargetScope& scope, int repetition) {
  return scope.repetition == 0 || scope.repetition == repetition;
}

// A lab operator as the virtual design has them: the sex, stature and arm
// length of their trial.
scene::OperatorEntry OperatorOf(const data::LabTrial& t) {
  scene::OperatorEntry op;
  op.name = t.operator_id;
  op.sex = t.sex;
  op.height = t.height;
  op.arm_length = t.arm_length;
  return op;
}

// Mean of times with variance s^2 / n; needs n >= 2.
Statistic MeanStatistic(const std::vector<double>& times) {
  const stats::Summary s = stats::Summarize(times);
  Statistic out;
  out.n = static_cast<int>(times.size());
  out.value = s.mean.value_or(std::numeric_limits<double>::quiet_NaN());
  out.variance = s.standard_error ? *s.standard_error * *s.standard_error
                                  : std::numeric_limits<double>::quiet_NaN();
  return out;
}

Statistic RateStatistic(int successes, int n) {
  Statistic out;
  out.n = n;
  out.value = n > 0 ? static_cast<double>(successes) / n
                    : std::numeric_limits<double>::quiet_NaN();
  const double p = (successes + 1.0) / (n + 2.0);
  out.variance = p * (1 - p) / std::max(n, 1);
  return out;
}

// Whether a lab row's text field matches a target's ("" in the target: any).
bool Matches(const std::string& wanted, const std::string& row) {
  return wanted.empty() || wanted == row;
}

// The row of `rows` (segments.csv or summaries.csv, the file `file`) that
// answers `spec` among those `fits` accepts: the first whose condition is the
// spec's; for a spec without a condition and no row without one, the rows of
// the one condition they share (rows of several conditions: an InputError,
// the spec must name one). None: nullptr.
template <typename Row, typename Fits>
const Row* ReportedRow(const std::vector<Row>& rows, const Fits& fits,
                       const TargetSpec& spec, const std::string& file,
                       const std::string& experiment_file) {
  const Row* any = nullptr;
  for (const Row& r : rows)
    if (fits(r) && r.condition == spec.condition) return &r;
  if (!spec.condition.empty()) return nullptr;
  for (const Row& r : rows) {
    if (!fits(r)) continue;
    if (any && any->condition != r.condition)
      throw InputError(
          experiment_file, spec.pointer + "/condition", "(missing)",
          fmt::format("the lab reports {} of {}{} for condition '{}' ({}, line "
                      "{}) and '{}' (line {}): name the one to read",
                      spec.quantity, spec.part,
                      spec.segment > 0 ? fmt::format(", segment {}", spec.segment) : "",
                      any->condition, file, any->line, r.condition, r.line));
    if (!any) any = &r;
  }
  return any;
}

// Whether a summary's instant is a target's: the same time up to the
// rounding of a unit's conversion (3000 ms against 3 s).
bool SameInstant(double row, double target) {
  return std::fabs(row - target) <= 1e-9 * std::max(1.0, std::fabs(target));
}

// A statistic the lab reports without its trials, for a target: a segment's
// attempts and successes (segments.csv), or a row of summaries.csv with the
// target's quantity, part ("all" matches a row for the whole assembly),
// segment and condition (ReportedRow), and for eta and lambda_c instant. Its
// variance: sd^2 / n when the row gives both; for a rate with n, that of a
// rate of n trials (the Laplace estimate, as for trials); for a mean (a
// time, eta, lambda_c) with n = 1 and no sd, a single draw
// (Statistic::single_draw); else the reading uncertainty's (a half-width
// taken as 1.96 sd). Nothing found: nullopt. Found without any uncertainty:
// an InputError, since a residual needs a weight, or with Unweighted::kPoint
// the value with a NaN variance.
std::optional<Statistic> ReportedStatistic(const data::LabDataset& lab,
                                           const TargetSpec& spec,
                                           const std::string& experiment_file,
                                           Unweighted unweighted) {
  if (spec.quantity == "success_rate" && spec.segment > 0)
    if (const data::LabSegment* g = ReportedRow(
            lab.segments,
            [&](const data::LabSegment& s) { return s.segment == spec.segment; }, spec,
            lab.segments_file, experiment_file))
      return RateStatistic(g->successes, g->attempts);
  const data::LabSummary* found = ReportedRow(
      lab.summaries,
      [&](const data::LabSummary& r) {
        return r.quantity == spec.quantity && r.part == spec.part &&
               r.segment == spec.segment &&
               (!scene::AtInstant(spec.quantity) || SameInstant(r.instant, spec.instant));
      },
      spec, lab.summaries_file, experiment_file);
  if (!found) return std::nullopt;
  const data::LabSummary& r = *found;
  Statistic out;
  out.value = r.value;
  out.n = r.n;
  if (std::isfinite(r.sd) && r.n > 0) {
    out.variance = r.sd * r.sd / r.n;
  } else if (spec.quantity != "success_rate" && r.n == 1) {
    out.single_draw = true;
    out.variance = std::numeric_limits<double>::quiet_NaN();
  } else if (spec.quantity == "success_rate" && r.n > 0) {
    const double p = (r.value * r.n + 1.0) / (r.n + 2.0);
    out.variance = p * (1 - p) / r.n;
  } else if (std::isfinite(r.uncertainty) && r.uncertainty > 0) {
    out.variance = (r.uncertainty / 1.96) * (r.uncertainty / 1.96);
  } else if (unweighted == Unweighted::kPoint) {
    out.variance = std::numeric_limits<double>::quiet_NaN();
  } else {
    throw InputError(
        experiment_file, spec.pointer, spec.quantity,
        fmt::format("the lab reports {} = {} ({}, line {}) without sd and n or "
                    "an uncertainty: a calibration cannot weigh it",
                    r.quantity, r.value, lab.summaries_file, r.line));
  }
  return out;
}

// eta (Eq. 2) or lambda_c (Eq. 3) of a row of factors.
double FactorOf(const human::FactorValues& v, const std::string& quantity) {
  return quantity == "eta" ? v.eta : v.lambda_c;
}

// "operator 'male 1', condition 'good', repetition 1": a track's trial.
std::string TrackWhere(const data::SensorTrack& track) {
  return fmt::format("operator '{}', condition '{}', repetition {}", track.operator_id,
                     track.condition, track.repetition);
}

// The lab trial a track records: the row of trials.csv with its operator,
// condition and repetition (of one part). An InputError naming the track's
// file when there is none, or rows of several parts.
const data::LabTrial& TrialOfTrack(const data::LabDataset& lab,
                                   const data::SensorTrack& track) {
  const data::LabTrial* found = nullptr;
  for (const data::LabTrial& t : lab.trials) {
    if (t.operator_id != track.operator_id || t.condition != track.condition ||
        t.repetition != track.repetition)
      continue;
    if (found && found->part != t.part)
      throw InputError(
          track.file, TrackWhere(track), track.operator_id,
          fmt::format("{} has trials of parts '{}' (line {}) and '{}' (line {}) for this "
                      "operator, condition and repetition: a track records one trial, "
                      "so its part is ambiguous",
                      lab.trials_file, found->part, found->line, t.part, t.line));
    if (!found) found = &t;
  }
  if (!found)
    throw InputError(
        track.file, TrackWhere(track), track.operator_id,
        fmt::format("{} has no trial of this operator, condition and repetition: a "
                    "track's part, and its operator's stature and arm length (r's "
                    "breakpoints, Fig. 4), come from its trial",
                    lab.trials_file.empty() ? "the dataset" : lab.trials_file));
  return *found;
}

// eta or lambda_c of one virtual cycle at the target's instant
// (AddAtInstant): the decision trace of its trial of the target's part, or
// for "all" of every trial on the cycle's clock (a part's rows from its start
// in the cycle). A trial, or for "all" a cycle, that failed as a computation
// says nothing (no count); a part the cycle never reached gives no trial.
void AddCycleAtInstant(const experiment::CycleResult& c, const TargetSpec& spec,
                       const std::string& op, TargetSamples* samples) {
  const bool all = spec.part == kAllParts;
  if (all && c.numerical_failure) return;
  std::vector<double> times, values;
  double end = 0;
  bool found = false;
  for (const experiment::PartRun& p : c.parts) {
    if (!all && p.trial.part != spec.part) continue;
    if (sim::IsComputationFailure(p.trial.status)) return;
    VAHF_CHECK(!p.trial.trace.empty(),
               "eta and lambda_c targets read the decision trace: run the design "
               "with record_trace");
    const double offset = all ? p.start_time : 0.0;
    for (const sim::TraceRow& row : p.trial.trace) {
      // The next part's first decision may fall on the instant the last one ended.
      if (!times.empty() && !(offset + row.time > times.back())) continue;
      times.push_back(offset + row.time);
      values.push_back(FactorOf(row.factors, spec.quantity));
    }
    end = offset + p.trial.end_time;
    found = true;
  }
  if (found) AddAtInstant(times, values, end, spec.instant, op, samples);
}

// "the lab dataset lab.json (operator male 1)"
std::string LabWhere(const data::LabDataset& lab, const std::string& op) {
  return "the lab dataset " + lab.file + (op.empty() ? "" : " (operator " + op + ")");
}

// A target's lab side that is neither trials (tracks) nor a report: the
// InputError that says what the lab lacks.
[[noreturn]] void ThrowNothingFor(const data::LabDataset& lab, const TargetSpec& spec,
                                  const std::string& op,
                                  const std::string& experiment_file) {
  const bool instant = scene::AtInstant(spec.quantity);
  throw InputError(
      experiment_file, spec.pointer, spec.part,
      LabWhere(lab, op) + " has no " + (instant ? "sensor tracks" : "trials") +
          " of this part" +
          (spec.condition.empty() ? "" : " in condition '" + spec.condition + "'") +
          (spec.by_operator
               ? ""
               : " and reports no " + spec.quantity +
                     (spec.segment > 0 ? fmt::format(" of segment {}", spec.segment)
                                       : "") +
                     (instant ? fmt::format(" at {:g} s", spec.instant) : "") +
                     " for it"));
}

// One target's lab statistic (LabTargets): of its trials or tracks, else
// what the lab reports.
Target LabTarget(const scene::Scene& scene, const data::LabDataset& lab,
                 const TargetSpec& spec, const TargetScope& scope,
                 const std::string& experiment_file, Unweighted unweighted) {
  const std::string& op = scope.operator_id;
  const TargetSamples samples = LabSamples(scene, lab, spec, scope);
  Target target = MakeTarget(spec, scope);
  const bool instant = scene::AtInstant(spec.quantity);
  const bool none = instant ? samples.Read() == 0 : samples.attempts == 0;
  // Without trials (tracks), what the lab reports: a segment's counts or a summary.
  if (none && !spec.by_operator && !spec.by_repetition)
    if (std::optional<Statistic> reported =
            ReportedStatistic(lab, spec, experiment_file, unweighted)) {
      target.lab = *reported;
      return target;
    }
  if (none) ThrowNothingFor(lab, spec, op, experiment_file);
  if (instant && samples.times.size() < 2)
    throw InputError(
        experiment_file, spec.pointer, spec.part,
        fmt::format("{} has {} value(s) of {} at {:g} s from its {} track(s) of this "
                    "part ({} NaN, {} over before the instant or not yet at their "
                    "first value); a mean and its variance need at least 2",
                    LabWhere(lab, op), samples.times.size(), spec.quantity, spec.instant,
                    samples.Read(), samples.nan_values, samples.no_value));
  if (spec.quantity == "assembly_time" && samples.times.size() < 2)
    throw InputError(experiment_file, spec.pointer, spec.part,
                     fmt::format("{} has {} successful trial(s) of this "
                                 "part; a mean time and its variance need at least 2",
                                 LabWhere(lab, op), samples.times.size()));
  target.lab = samples.Of(spec.quantity);
  target.from_tracks = instant;
  return target;
}

}  // namespace

double LabVariance(const Statistic& lab, const Statistic& virt) {
  return lab.single_draw ? virt.variance * virt.n : lab.variance;
}

void TargetSamples::Add(bool success, double time, const std::string& op) {
  ++attempts;
  if (!success) return;
  ++successes;
  times.push_back(time);
  auto it = std::find_if(by_operator.begin(), by_operator.end(),
                         [&](const auto& e) { return e.first == op; });
  if (it == by_operator.end()) it = by_operator.insert(by_operator.end(), {op, {}});
  it->second.push_back(time);
}

Statistic TargetSamples::Of(const std::string& quantity) const {
  if (quantity == "success_rate") return RateStatistic(successes, attempts);
  Statistic out = MeanStatistic(times);
  double sum = 0;
  for (const auto& [op, t] : by_operator) {
    if (t.size() < 2) return out;
    const double sd = stats::SampleStandardDeviation(t);
    sum += static_cast<double>(t.size()) * sd * sd;
  }
  if (by_operator.size() > 1)
    out.variance =
        sum / (static_cast<double>(times.size()) * static_cast<double>(times.size()));
  return out;
}

std::vector<TargetScope> TargetScopes(const TargetSpec& spec,
                                      const data::LabDataset& lab) {
  std::vector<TargetScope> out;
  if (spec.by_operator)
    for (const std::string& op : LabOperators(lab)) out.push_back({op, 0});
  else if (spec.by_repetition)
    for (int r : LabRepetitions(lab)) out.push_back({"", r});
  else
    out.push_back({});
  return out;
}

TargetSamples LabSamples(const scene::Scene& scene, const data::LabDataset& lab,
                         const TargetSpec& spec, const TargetScope& scope) {
  if (scene::AtInstant(spec.quantity)) return TrackSamples(scene, lab, spec, scope);
  TargetSamples samples;
  if (spec.segment > 0) return samples;  // trials carry no segment
  for (const data::LabTrial& t : lab.trials)
    if (t.part == spec.part && Matches(scope.operator_id, t.operator_id) &&
        Matches(spec.condition, t.condition) && OfRepetition(scope, t.repetition))
      samples.Add(t.success, t.time, t.operator_id);
  return samples;
}

void AddAtInstant(const std::vector<double>& times, const std::vector<double>& values,
                  double end, double instant, const std::string& operator_id,
                  TargetSamples* samples) {
  VAHF_CHECK(times.size() == values.size(), "AddAtInstant: one value per row");
  // The first row after the instant; the one before it is the last at or before.
  const auto after = std::upper_bound(times.begin(), times.end(), instant);
  if (end < instant || after == times.begin()) {
    ++samples->no_value;
    return;
  }
  const double v = values[static_cast<std::size_t>(after - times.begin()) - 1];
  if (std::isnan(v)) {
    ++samples->nan_values;
    return;
  }
  samples->Add(true, v, operator_id);
}

TargetSamples TrackSamples(const scene::Scene& scene, const data::LabDataset& lab,
                           const TargetSpec& spec, const TargetScope& scope) {
  TargetSamples samples;
  for (const data::SensorTrack& track : lab.tracks) {
    if (!Matches(spec.condition, track.condition) ||
        !Matches(scope.operator_id, track.operator_id) ||
        !OfRepetition(scope, track.repetition))
      continue;
    const data::LabTrial& trial = TrialOfTrack(lab, track);
    if (trial.part != spec.part || track.samples.empty()) continue;
    // The operator as the virtual design has them (LabConditions), and the
    // curves every trial of theirs evaluates.
    const scene::OperatorEntry op = OperatorOf(trial);
    const human::FactorCurves curves =
        sim::OperatorFactorCurves(*experiment::OperatorCondition(scene, op).scene);
    std::vector<double> times, values;
    for (const data::TrackFactors& row : data::FactorsFromTrack(track, curves)) {
      times.push_back(row.time);
      values.push_back(FactorOf(row.values, spec.quantity));
    }
    AddAtInstant(times, values, track.samples.back().time, spec.instant,
                 track.operator_id, &samples);
  }
  return samples;
}

std::vector<int> LabRepetitions(const data::LabDataset& lab) {
  std::vector<int> out;
  for (const data::LabTrial& t : lab.trials) out.push_back(t.repetition);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::string> LabOperators(const data::LabDataset& lab) {
  std::vector<std::string> out;
  for (const data::LabTrial* t : FirstTrialOfEachOperator(lab))
    out.push_back(t->operator_id);
  return out;
}

Target MakeTarget(const TargetSpec& spec, const TargetScope& scope) {
  const std::string& operator_id = scope.operator_id;
  Target target;
  target.spec = spec;
  target.operator_id = operator_id;
  target.repetition = scope.repetition;
  target.unit = UnitOf(spec.quantity);
  target.label =
      spec.quantity + " of " + spec.part +
      (spec.segment > 0 ? fmt::format(", segment {}", spec.segment) : "") +
      (scene::AtInstant(spec.quantity) ? fmt::format(" at {:g} s", spec.instant) : "") +
      (spec.condition.empty() ? "" : ", " + spec.condition) +
      (operator_id.empty() ? "" : ", operator " + operator_id) +
      (scope.repetition > 0 ? fmt::format(", repetition {}", scope.repetition) : "");
  return target;
}

const std::vector<std::string>& TargetQuantities() { return scene::FitQuantities(); }

void PoolVariances(const std::vector<Target>& targets, std::vector<Statistic>* stats) {
  VAHF_CHECK(stats->size() == targets.size(), "one statistic per target");
  // A spec's targets follow each other: [first, end) is one spec's.
  for (std::size_t first = 0, end = 0; first < targets.size(); first = end) {
    const TargetSpec& spec = targets[first].spec;
    end = first;
    while (end < targets.size() && targets[end].spec.pointer == spec.pointer) ++end;
    if (!spec.pooled_variance) continue;
    double sum = 0, dof = 0;
    for (std::size_t i = first; i < end; ++i) {
      const Statistic& s = (*stats)[i];
      if (s.n < 2 || !std::isfinite(s.variance)) continue;
      sum += s.variance * s.n * (s.n - 1);  // (n - 1) s^2, s^2 = n var
      dof += s.n - 1;
    }
    if (!(dof > 0)) continue;
    for (std::size_t i = first; i < end; ++i) {
      Statistic& s = (*stats)[i];
      if (s.n >= 1 && !s.single_draw) s.variance = sum / dof / s.n;
    }
  }
}

std::vector<Target> LabTargets(const scene::Scene& scene, const data::LabDataset& lab,
                               const std::vector<TargetSpec>& specs,
                               const std::string& experiment_file,
                               Unweighted unweighted) {
  std::vector<Target> out;
  for (const TargetSpec& spec : specs) {
    for (const TargetScope& scope : TargetScopes(spec, lab))
      out.push_back(LabTarget(scene, lab, spec, scope, experiment_file, unweighted));
  }
  std::vector<Statistic> lab_stats;
  for (const Target& t : out) lab_stats.push_back(t.lab);
  PoolVariances(out, &lab_stats);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].lab = lab_stats[i];
  return out;
}

std::vector<experiment::Condition> LabConditions(const scene::Scene& scene,
                                                 const data::LabDataset& lab,
                                                 int trials) {
  std::vector<experiment::Condition> out;
  const std::vector<int> repetitions = LabRepetitions(lab);
  const int r = repetitions.empty() ? 0 : repetitions.back();
  if (scene.params.learning.model != "none" && r > 0 && trials % r != 0)
    throw InputError(lab.folder + "/" + lab.trials_file, "repetition", std::to_string(r),
                     fmt::format("with learning model '{}' the virtual operators repeat "
                                 "the task as the lab's did, each repetition 1-{} "
                                 "equally often: the cycles per operator ({}) must be "
                                 "a multiple of {}",
                                 scene.params.learning.model, r, trials, r));
  for (const data::LabTrial* t : FirstTrialOfEachOperator(lab)) {
    const scene::OperatorEntry op = OperatorOf(*t);
    // The reach curve needs D1 < D2 < D3 for each operator (as a scene's or an
    // experiment's operators do): a lab operator the scene's reach parameters
    // cannot take is named with the row that introduced them.
    const std::string reach = scene.params.reach.Violation(op.arm_length, op.height);
    if (!reach.empty())
      throw InputError(
          lab.folder + "/" + lab.trials_file,
          fmt::format("line {}, operator {}", t->line, op.name),
          fmt::format("height {} m, arm_length {} m", op.height, op.arm_length),
          "with scene '" + scene.name + "''s reach parameters: " + reach);
    out.push_back(experiment::OperatorCondition(scene, op));
    out.back().cycle_offset =
        static_cast<std::uint64_t>(out.size() - 1) * static_cast<std::uint64_t>(trials);
    out.back().repetitions = r;
  }
  if (out.empty())
    out.push_back(
        {"scene operator", scene.op.sex, std::make_shared<const scene::Scene>(scene)});
  return out;
}

std::string LabReachViolation(const scene::Scene& scene, const data::LabDataset& lab) {
  for (const data::LabTrial* t : FirstTrialOfEachOperator(lab)) {
    const std::string reach = scene.params.reach.Violation(t->arm_length, t->height);
    if (!reach.empty())
      return fmt::format("{}/{} line {}, operator {} (height {} m, arm_length {} m): {}",
                         lab.folder, lab.trials_file, t->line, t->operator_id, t->height,
                         t->arm_length, reach);
  }
  return {};
}

Statistic VirtualStatistic(const Target& target, const experiment::DesignRun& run,
                           const std::vector<int>& segments) {
  return VirtualSamples(target, run, segments).Of(target.spec.quantity);
}

TargetSamples VirtualSamples(const Target& target, const experiment::DesignRun& run,
                             const std::vector<int>& segments) {
  TargetSamples samples;
  for (const experiment::CycleRecord& r : run.records) {
    if (!target.operator_id.empty() &&
        run.conditions[r.condition].name != target.operator_id)
      continue;
    if (target.repetition > 0 && r.repetition != target.repetition) continue;
    if (target.spec.segment > 0 && (r.condition >= segments.size() ||
                                    segments[r.condition] != target.spec.segment - 1))
      continue;
    const experiment::CycleResult& c = r.result;
    const std::string& op = run.conditions[r.condition].name;
    if (scene::AtInstant(target.spec.quantity)) {
      AddCycleAtInstant(c, target.spec, op, &samples);
      continue;
    }
    if (target.spec.part == kAllParts) {
      if (!c.numerical_failure) samples.Add(c.completed, c.time, op);
      continue;
    }
    for (const experiment::PartRun& p : c.parts) {
      if (p.trial.part != target.spec.part || sim::IsComputationFailure(p.trial.status))
        continue;
      samples.Add(p.trial.status == sim::Status::kCompleted, p.trial.completion_time, op);
    }
  }
  return samples;
}

}  // namespace vahf::calibrate
