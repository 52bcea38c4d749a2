#include "vahf/compare/comparison.h"

#include <fmt/format.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "vahf/core/error.h"
#include "vahf/stats/equivalence.h"
#include "vahf/stats/proportion.h"

namespace vahf::compare {
namespace {

constexpr double kAlpha = 0.05;  // of the equivalence test

stats::Interval MeanInterval(const std::vector<double>& xs) {
  const stats::Summary s = stats::Summarize(xs);
  if (s.ci) return *s.ci;
  const double m = s.mean.value_or(std::nan(""));
  return {m, m};
}

std::string Value(double x, const std::string& unit) {
  return unit == "s" ? fmt::format("{:.4g} s", x) : fmt::format("{:.3g}", x);
}

// What the samples of a mean are: "successful trials" for a time, "values
// at 3 s" for eta and lambda_c.
std::string SamplesOf(const calibrate::Target& target) {
  return scene::AtInstant(target.spec.quantity)
             ? fmt::format("values at {:g} s", target.spec.instant)
             : "successful trials";
}

// A mean (a time, eta or lambda_c) from both sides' samples: Welch, TOST,
// the area metric and KS.
void CompareMeans(QuantityComparison* q) {
  const std::vector<double>& a = q->virt.times;
  const std::vector<double>& b = q->lab.times;
  q->lab_ci = MeanInterval(b);
  q->virtual_ci = MeanInterval(a);
  if (a.size() < 2 || b.size() < 2) {
    q->untestable_reason =
        fmt::format("{} virtual and {} lab {}; a mean's interval needs 2 on each side",
                    a.size(), b.size(), SamplesOf(q->target));
    return;
  }
  stats::TostResult tost;
  try {
    tost = stats::EquivalenceTest(a, b, q->margin);
  } catch (const ComputationError& e) {
    if (e.reason() != ComputationError::Reason::kZeroVariance) throw;
    q->untestable_reason = "both samples have zero variance: no t statistic";
    return;
  }
  q->testable = true;
  q->difference = tost.welch.mean_difference;
  q->ci95 = tost.welch.ci;
  q->ci90 = tost.ci90;
  q->tost_p = tost.p;
  q->area_metric = stats::AreaValidationMetric(a, b);
  q->ks = stats::KolmogorovSmirnovTest(a, b);
}

// The normal approximation of a difference d with standard error se: its 95 %
// and 90 % intervals and the TOST p against the margin (Schuirmann 1987's two
// one-sided tests on the normal statistic).
void NormalTest(QuantityComparison* q, double d, double se) {
  const double z95 = gsl_cdf_ugaussian_Pinv(0.975), z90 = gsl_cdf_ugaussian_Pinv(0.95);
  q->testable = true;
  q->ci95 = {d - z95 * se, d + z95 * se};
  q->ci90 = {d - z90 * se, d + z90 * se};
  q->tost_p = std::max(gsl_cdf_ugaussian_Q((d + q->margin) / se),
                       gsl_cdf_ugaussian_P((d - q->margin) / se));
}

// Proportions: the difference of Laplace-smoothed rates (successes + 1) /
// (n + 2) has a normal interval that stays defined at 0 and 1 (Agresti and
// Caffo, Am. Stat. 54(4) 280, 2000: add one success and one failure to each
// sample); the TOST on it is the normal one. The area between the two
// Bernoulli distributions is |p_v - p_l|.
void CompareRates(QuantityComparison* q) {
  const stats::Count v{q->virt.successes, q->virt.attempts};
  const stats::Count l{q->lab.successes, q->lab.attempts};
  q->virtual_ci = stats::WilsonInterval(v);
  q->lab_ci = stats::WilsonInterval(l);
  const double kv = static_cast<double>(v.successes), nv = static_cast<double>(v.trials);
  const double kl = static_cast<double>(l.successes), nl = static_cast<double>(l.trials);
  const double pv = kv / nv, pl = kl / nl;
  const double sv = (kv + 1) / (nv + 2), sl = (kl + 1) / (nl + 2);
  NormalTest(q, sv - sl, std::sqrt(sv * (1 - sv) / (nv + 2) + sl * (1 - sl) / (nl + 2)));
  q->difference = pv - pl;
  q->area_metric = std::fabs(pv - pl);
}

// Whether the quantity agrees, and the verdict in a sentence: why untestable,
// or the difference, its 90 % interval against the margin and the TOST p, and
// for a reported statistic what it was weighed by.
void SetVerdict(QuantityComparison* q) {
  const std::string& u = q->target.unit;
  q->agree = q->testable && q->tost_p < kAlpha;
  if (!q->testable) {
    q->verdict = "untestable: " + q->untestable_reason;
    return;
  }
  std::string basis;
  if (q->reported)
    basis = q->target.lab.single_draw
                ? "; normal approximation against the one value the lab reports, weighed "
                  "as a single draw with the virtual per-sample spread"
                : "; normal approximation against the value the lab reports";
  q->verdict = fmt::format(
      "{}: the difference (virtual - lab) is {} with 90 % interval [{}, {}], {} the "
      "+-{} margin (TOST p = {:.3g}){}",
      q->agree ? "agree" : "not shown to agree", Value(q->difference, u),
      Value(q->ci90.lower, u), Value(q->ci90.upper, u),
      q->agree ? "inside" : "not inside", Value(q->margin, u), q->tost_p, basis);
}

// Why the virtual side gave nothing: no trial of the part, or for eta and
// lambda_c none with a value at the instant.
std::string NoVirtualReason(const calibrate::Target& target,
                            const calibrate::TargetSamples& virt) {
  if (!scene::AtInstant(target.spec.quantity) || virt.Read() == 0)
    return "the virtual design attempted this part in no cycle";
  return fmt::format(
      "no virtual trial gave {} at {:g} s ({} over before it, {} NaN there)",
      target.spec.quantity, target.spec.instant, virt.no_value, virt.nan_values);
}

// A comparison of `target` with its virtual side filled in.
QuantityComparison WithVirtual(const calibrate::Target& target, double margin,
                               const calibrate::TargetSamples& virt) {
  QuantityComparison q;
  q.target = target;
  q.margin = margin;
  q.virt = virt;
  q.virtual_stat = virt.Of(target.spec.quantity);
  return q;
}

}  // namespace

QuantityComparison CompareSamples(const calibrate::Target& target, double margin,
                                  const calibrate::TargetSamples& lab,
                                  const calibrate::TargetSamples& virt) {
  QuantityComparison q = WithVirtual(target, margin, virt);
  q.lab = lab;
  q.lab_variance = target.lab.variance;
  const bool mean = target.spec.quantity != "success_rate";
  if (virt.attempts == 0) {
    q.untestable_reason = NoVirtualReason(target, virt);
  } else if (mean) {
    CompareMeans(&q);
  } else {
    CompareRates(&q);
  }
  if (!q.ks)
    q.ks_unavailable =
        mean ? q.untestable_reason : "a rate is not a distribution of times";
  SetVerdict(&q);
  return q;
}

QuantityComparison CompareReported(const calibrate::Target& target, double margin,
                                   const calibrate::TargetSamples& virt) {
  QuantityComparison q = WithVirtual(target, margin, virt);
  q.reported = true;
  q.ks_unavailable = "the lab reports a summary, not samples";
  const calibrate::Statistic& l = target.lab;
  const bool mean = target.spec.quantity != "success_rate";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  q.virtual_ci = mean ? MeanInterval(virt.times)
                 : virt.attempts > 0
                     ? stats::WilsonInterval({virt.successes, virt.attempts})
                     : stats::Interval{nan, nan};
  q.lab_variance = calibrate::LabVariance(l, q.virtual_stat);
  q.lab_ci = {nan, nan};
  if (std::isfinite(q.lab_variance)) {
    const double h = gsl_cdf_ugaussian_Pinv(0.975) * std::sqrt(q.lab_variance);
    q.lab_ci = {l.value - h, l.value + h};
    if (q.target.unit == "1")  // a rate, eta or lambda_c lies in [0, 1]
      q.lab_ci = {std::max(0.0, q.lab_ci.lower), std::min(1.0, q.lab_ci.upper)};
  }
  const double var = q.virtual_stat.variance + q.lab_variance;
  if (virt.attempts == 0) {
    q.untestable_reason = NoVirtualReason(target, virt);
  } else if (mean && virt.times.size() < 2) {
    q.untestable_reason =
        fmt::format("{} virtual {}; the virtual mean's variance needs 2",
                    virt.times.size(), SamplesOf(target));
  } else if (!l.single_draw && !std::isfinite(l.variance)) {
    q.untestable_reason = fmt::format(
        "the lab reports {} without sd and n or an uncertainty: with no spread on the "
        "lab's "
        "side the difference has no interval",
        Value(l.value, target.unit));
  } else if (!(var > 0)) {
    q.untestable_reason = "both sides have zero variance: no normal statistic";
  } else {
    q.difference = q.virtual_stat.value - l.value;
    NormalTest(&q, q.difference, std::sqrt(var));
    // Against a point value x the lab's distribution is a step at x: for a
    // mean the area is the mean |v_i - x|, for a rate |p_v - p_l|.
    q.area_metric = mean ? stats::AreaValidationMetric(virt.times, {l.value})
                         : std::fabs(q.difference);
  }
  SetVerdict(&q);
  return q;
}

std::vector<LabQuantity> LabSide(const scene::Scene& scene, const data::LabDataset& lab,
                                 const ComparisonDesign& design,
                                 const std::string& experiment_file) {
  std::vector<LabQuantity> out;
  for (const scene::FitTarget& spec : design.quantities) {
    const std::vector<calibrate::TargetScope> scopes = calibrate::TargetScopes(spec, lab);
    if (scopes.empty())
      throw InputError(experiment_file, spec.pointer + "/by",
                       spec.by_operator ? "operator" : "repetition",
                       "the lab dataset " + lab.file + " has no trials, hence no " +
                           (spec.by_operator ? "operators" : "repetitions"));
    for (const calibrate::TargetScope& scope : scopes) {
      const std::string& op = scope.operator_id;
      LabQuantity q;
      q.margin = spec.margin;
      q.samples = calibrate::LabSamples(scene, lab, spec, scope);
      // eta and lambda_c: the lab's tracks, even when too few give a value
      // (the comparison then says so).
      const bool instant = scene::AtInstant(spec.quantity);
      if (instant ? q.samples.Read() > 0 : q.samples.attempts > 0) {
        q.target = calibrate::MakeTarget(spec, scope);
        q.target.lab = q.samples.Of(spec.quantity);
        q.target.from_tracks = instant;
      } else if (!op.empty() || scope.repetition > 0) {
        // What a lab reports is never an operator's or a repetition's.
        throw InputError(
            experiment_file, spec.pointer, spec.part,
            "the lab dataset " + lab.file +
                (op.empty() ? fmt::format(" (repetition {})", scope.repetition)
                            : " (operator " + op + ")") +
                " has no " + (instant ? "sensor tracks" : "trials") + " of this part");
      } else {
        // No trials: what the lab reports (an InputError when it reports
        // nothing either).
        q.target = calibrate::LabTargets(scene, lab, {spec}, experiment_file,
                                         calibrate::Unweighted::kPoint)
                       .front();
        q.reported = true;
      }
      out.push_back(std::move(q));
    }
  }
  return out;
}

std::string LabBasis(const calibrate::Target& target, bool reported) {
  if (!reported) return target.from_tracks ? "tracks" : "trials";
  if (target.lab.single_draw) return "reported once, no spread (a single draw)";
  return std::isfinite(target.lab.variance) ? "reported" : "reported, no spread";
}

ComparisonResult Compare(const scene::Scene& scene, const data::LabDataset& lab,
                         const ComparisonDesign& design,
                         const std::string& experiment_file, std::uint64_t seed,
                         int trials, const experiment::RunnerOptions& options,
                         const experiment::RunnerOptions& pilot_options) {
  // The lab's side first: a quantity it cannot supply costs no simulation.
  const std::vector<LabQuantity> planned = LabSide(scene, lab, design, experiment_file);
  bool operators = false, trace = false;
  std::vector<int> segments;  // 0-based, increasing
  for (const LabQuantity& p : planned) {
    const int s = p.target.spec.segment;
    if (s == 0) operators = true;
    // eta and lambda_c are read off the decision trace.
    if (scene::AtInstant(p.target.spec.quantity)) trace = true;
    if (s > 0 && std::find(segments.begin(), segments.end(), s - 1) == segments.end())
      segments.push_back(s - 1);
  }
  std::sort(segments.begin(), segments.end());
  ComparisonResult out;
  if (operators)
    out.run = experiment::RunDesign(calibrate::LabConditions(scene, lab, trials), trials,
                                    seed, trace, options);
  // The scene's operator works the hour; only the segments the quantities
  // name are run (the pilot, which measures the work rate, always is), as a
  // calibration runs them.
  if (!segments.empty())
    out.fatigue = experiment::RunFatigue(std::make_shared<const scene::Scene>(scene),
                                         design.fatigue, trials, seed, options,
                                         pilot_options, segments);
  for (const LabQuantity& p : planned) {
    const calibrate::TargetSamples virt =
        p.target.spec.segment > 0
            ? calibrate::VirtualSamples(p.target, out.fatigue.run, out.fatigue.segments)
            : calibrate::VirtualSamples(p.target, out.run);
    out.quantities.push_back(p.reported
                                 ? CompareReported(p.target, p.margin, virt)
                                 : CompareSamples(p.target, p.margin, p.samples, virt));
  }
  return out;
}

}  // namespace vahf::compare
