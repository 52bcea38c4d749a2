#include "vahf/compare/comparison.h"

#include <fmt/format.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

void CompareTimes(QuantityComparison* q) {
  const std::vector<double>& a = q->virt.times;
  const std::vector<double>& b = q->lab.times;
  q->lab_ci = MeanInterval(b);
  q->virtual_ci = MeanInterval(a);
  if (a.size() < 2 || b.size() < 2) {
    q->untestable_reason = fmt::format(
        "{} virtual and {} lab successful trials; a mean's interval needs 2 on each side",
        a.size(), b.size());
    return;
  }
  stats::TostResult tost;
  try {
    tost = stats::EquivalenceTest(a, b, q->margin);
  } catch (const std::invalid_argument&) {
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
  const double se = std::sqrt(sv * (1 - sv) / (nv + 2) + sl * (1 - sl) / (nl + 2));
  const double d = sv - sl;
  q->testable = true;
  q->difference = pv - pl;
  const double z95 = gsl_cdf_ugaussian_Pinv(0.975), z90 = gsl_cdf_ugaussian_Pinv(0.95);
  q->ci95 = {d - z95 * se, d + z95 * se};
  q->ci90 = {d - z90 * se, d + z90 * se};
  q->tost_p = std::max(gsl_cdf_ugaussian_Q((d + q->margin) / se),
                       gsl_cdf_ugaussian_P((d - q->margin) / se));
  q->area_metric = std::fabs(pv - pl);
}

}  // namespace

QuantityComparison CompareSamples(const calibrate::Target& target, double margin,
                                  const calibrate::TargetSamples& lab,
                                  const calibrate::TargetSamples& virt) {
  QuantityComparison q;
  q.target = target;
  q.margin = margin;
  q.lab = lab;
  q.virt = virt;
  q.virtual_stat = virt.Of(target.spec.quantity);
  if (virt.attempts == 0) {
    q.untestable_reason = "the virtual design attempted this part in no cycle";
  } else if (target.spec.quantity == "assembly_time") {
    CompareTimes(&q);
  } else {
    CompareRates(&q);
  }
  const std::string& u = target.unit;
  if (!q.testable) {
    q.verdict = "untestable: " + q.untestable_reason;
  } else {
    q.agree = q.tost_p < kAlpha;
    q.verdict = fmt::format(
        "{}: the difference (virtual - lab) is {} with 90 % interval [{}, {}], {} the "
        "+-{} margin (TOST p = {:.3g})",
        q.agree ? "agree" : "not shown to agree", Value(q.difference, u), Value(q.ci90.lower, u),
        Value(q.ci90.upper, u), q.agree ? "inside" : "not inside", Value(margin, u), q.tost_p);
  }
  return q;
}

ComparisonResult Compare(const scene::Scene& scene, const data::LabDataset& lab,
                         const scene::ComparisonDesign& design,
                         const std::string& experiment_file, std::uint64_t seed, int trials,
                         const experiment::RunnerOptions& options) {
  // The lab's side first: a quantity it cannot supply costs no simulation.
  struct Planned {
    calibrate::Target target;
    double margin;
    calibrate::TargetSamples lab;
  };
  std::vector<Planned> planned;
  for (const scene::FitTarget& spec : design.quantities) {
    const std::vector<std::string> operators =
        spec.by_operator ? calibrate::LabOperators(lab) : std::vector<std::string>{""};
    for (const std::string& op : operators) {
      calibrate::TargetSamples samples = calibrate::LabSamples(lab, spec, op);
      if (samples.attempts == 0)
        throw InputError(experiment_file, spec.pointer, spec.part,
                         "the lab dataset " + lab.file +
                             (op.empty() ? "" : " (operator " + op + ")") +
                             " has no trials of this part");
      calibrate::Target t = calibrate::MakeTarget(spec, op);
      t.lab = samples.Of(spec.quantity);
      planned.push_back({t, spec.margin, std::move(samples)});
    }
  }
  ComparisonResult out;
  out.run = experiment::RunDesign(calibrate::LabConditions(scene, lab, trials), trials, seed,
                                  false, options);
  for (const Planned& p : planned)
    out.quantities.push_back(
        CompareSamples(p.target, p.margin, p.lab, calibrate::VirtualSamples(p.target, out.run)));
  return out;
}

}  // namespace vahf::compare
