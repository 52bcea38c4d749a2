#include "vahf/report/precision.h"

#include <fmt/format.h>

#include <cmath>

#include "vahf/core/error.h"

namespace vahf::report {

std::string PartOutcome::StatusText() const {
  return reached ? sim::StatusName(status) : "not_reached";
}

PartComparison ComparePart(const std::vector<PartOutcome>& setting,
                           const std::vector<PartOutcome>& reference, int noise_trials) {
  VAHF_CHECK(setting.size() == reference.size(), "the same cycles under both");
  VAHF_CHECK(noise_trials >= 1, "noise_trials >= 1");
  PartComparison c;
  c.cycles = setting.size();
  std::vector<double> mine, theirs, differences, absolute, all_reference, steps,
      realizations;
  for (std::size_t j = 0; j < c.cycles; ++j) {
    const PartOutcome& s = setting[j];
    const PartOutcome& r = reference[j];
    if (s.reached != r.reached || (s.reached && s.status != r.status))
      ++c.outcome_differences;
    if (s.reached) {
      steps.push_back(static_cast<double>(s.steps));
      realizations.push_back(static_cast<double>(s.realizations));
    }
    if (s.completed()) ++c.completed;
    if (r.completed()) all_reference.push_back(r.completion_time);
    if (!s.completed() || !r.completed()) continue;
    mine.push_back(s.completion_time);
    theirs.push_back(r.completion_time);
    differences.push_back(s.completion_time - r.completion_time);
    absolute.push_back(std::fabs(differences.back()));
  }
  c.paired = differences.size();
  c.outcome_share = c.cycles ? static_cast<double>(c.outcome_differences) /
                                   static_cast<double>(c.cycles)
                             : 0.0;
  c.difference = stats::Summarize(differences);
  if (c.difference.ci)
    c.difference_bound =
        std::max(std::fabs(c.difference.ci->lower), std::fabs(c.difference.ci->upper));
  if (!absolute.empty()) c.mean_abs_difference = stats::Mean(absolute);
  c.reference_completed = all_reference.size();
  if (all_reference.size() >= 2) {
    c.reference_sd = stats::SampleStandardDeviation(all_reference);
    c.noise = *c.reference_sd / std::sqrt(static_cast<double>(noise_trials));
  }
  if (!mine.empty()) {
    c.ks = stats::KolmogorovSmirnovTest(mine, theirs);
    c.ks_shift = stats::KsEquivalentShift(theirs, c.ks->distance);
    if (c.noise) c.ks_noise_distance = stats::KsDistanceOfShift(theirs, *c.noise);
    c.p10 = stats::Quantile(mine, 0.1);
    c.p90 = stats::Quantile(mine, 0.9);
    c.reference_p10 = stats::Quantile(theirs, 0.1);
    c.reference_p90 = stats::Quantile(theirs, 0.9);
  }
  if (!steps.empty()) {
    c.steps_median = stats::Quantile(steps, 0.5);
    c.realizations_median = stats::Quantile(realizations, 0.5);
  }
  c.failures = RuleFailures(c);
  return c;
}

std::string RuleFailures(const PartComparison& c) {
  std::vector<std::string> why;
  if (c.paired < 2)
    why.push_back(
        fmt::format("{} cycle(s) completed the part under both: needs 2", c.paired));
  if (!c.noise)
    why.push_back(fmt::format(
        "the reference completed the part {} time(s): no noise to compare with",
        c.reference_completed));
  if (c.noise && c.difference_bound && !(*c.difference_bound < *c.noise))
    why.push_back(fmt::format("|mean difference| up to {:.3g} ms >= noise {:.3g} ms",
                              *c.difference_bound * 1e3, *c.noise * 1e3));
  if (c.noise && c.ks_shift && !(*c.ks_shift < *c.noise))
    why.push_back(
        fmt::format("KS distance {:.3f} (as a shift {:.3g} ms) >= noise {:.3g} ms",
                    c.ks->distance, *c.ks_shift * 1e3, *c.noise * 1e3));
  if (c.ks && c.ks->p_value < kKsLevel)
    why.push_back(
        fmt::format("KS distance {:.3f} tells the times from the reference's "
                    "(p = {:.2g} < {:g})",
                    c.ks->distance, c.ks->p_value, kKsLevel));
  if (!(c.outcome_share < kMaxOutcomeShare))
    why.push_back(fmt::format("outcome differs in {}/{} cycles ({:.0f} % >= {:.0f} %)",
                              c.outcome_differences, c.cycles, c.outcome_share * 100,
                              kMaxOutcomeShare * 100));
  std::string out;
  for (const std::string& w : why) out += (out.empty() ? "" : "; ") + w;
  return out;
}

WallSummary SummarizeWall(const std::vector<PartOutcome>& outcomes) {
  std::vector<double> wall;
  for (const PartOutcome& o : outcomes)
    if (o.reached) wall.push_back(o.wall_seconds);
  WallSummary w;
  w.n = wall.size();
  if (wall.empty()) return w;
  w.median = stats::Quantile(wall, 0.5);
  w.p10 = stats::Quantile(wall, 0.1);
  w.p90 = stats::Quantile(wall, 0.9);
  return w;
}

Recommendation Recommend(const std::vector<Candidate>& candidates) {
  std::optional<std::size_t> best;
  std::size_t meeting = 0;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const Candidate& c = candidates[k];
    if (!c.reference && !c.failures.empty()) continue;
    ++meeting;
    if (!best || c.cost < candidates[*best].cost) best = k;
  }
  VAHF_CHECK(best.has_value(), "the reference is among the candidates");
  const Candidate& chosen = candidates[*best];
  Recommendation r;
  r.index = *best;
  r.why = fmt::format(
      "{}: the cheapest of the {} of {} settings (the reference included) that meet the "
      "rule, {:.3g} s of wall per cycle",
      chosen.label, meeting, candidates.size(), chosen.cost);
  // Each cheaper one refused, with the first of its reasons.
  std::string refused;
  for (const Candidate& c : candidates) {
    if (!(c.cost < chosen.cost) || c.reference || c.failures.empty()) continue;
    const std::size_t end = c.failures.find("; ");
    refused +=
        fmt::format("{}{} ({:.3g} s: {}{})", refused.empty() ? "" : "; ", c.label, c.cost,
                    c.failures.substr(0, end), end == std::string::npos ? "" : "; ...");
  }
  if (!refused.empty()) r.why += "; cheaper but refused: " + refused;
  if (chosen.reference) r.why += "; no setting cheaper than the reference meets the rule";
  return r;
}

}  // namespace vahf::report
