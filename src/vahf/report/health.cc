#include "vahf/report/health.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "vahf/report/markdown.h"

namespace vahf::report {
namespace {

// The deepest contact is judged part trial by part trial against that
// trial's own bound (a tenth of its part's smallest radial clearance): the
// condition shows the trial that came nearest its bound, with its part. With
// no bound anywhere (no radial fit), the deepest contact of any trial.
struct ConditionHealth {
  std::int64_t cycles = 0, numerical_failures = 0;
  Warnings warnings;
  double max_penetration = 0, bound = 0;  // m; bound 0: no radial fit
  std::string part;                       // whose trial they are
};

// Whether a part trial's (depth, bound) lies nearer its bound than h's.
bool Nearer(double depth, double bound, const ConditionHealth& h) {
  if (bound > 0 && h.bound > 0) return depth * h.bound > h.max_penetration * bound;
  if (bound > 0 || h.bound > 0) return bound > 0;  // a bounded trial first
  return depth > h.max_penetration;
}

std::vector<ConditionHealth> Collect(const experiment::DesignRun& run) {
  std::vector<ConditionHealth> out(run.conditions.size());
  for (const experiment::CycleRecord& r : run.records) {
    ConditionHealth& h = out[r.condition];
    ++h.cycles;
    if (r.result.numerical_failure) ++h.numerical_failures;
    h.warnings.Add(r.result.warnings);
    for (const experiment::PartRun& p : r.result.parts) {
      const sim::TrialResult& t = p.trial;
      if (h.part.empty() || Nearer(t.max_penetration, t.penetration_bound, h)) {
        h.max_penetration = t.max_penetration;
        h.bound = t.penetration_bound;
        h.part = t.part;
      }
    }
  }
  return out;
}

}  // namespace

nlohmann::json HealthJson(const experiment::DesignRun& run) {
  nlohmann::json conditions = nlohmann::json::array();
  std::int64_t total = 0;
  const std::vector<ConditionHealth> health = Collect(run);
  for (std::size_t c = 0; c < health.size(); ++c) {
    const ConditionHealth& h = health[c];
    nlohmann::json warnings = nlohmann::json::object();
    for (int k = 0; k < kWarningKinds; ++k) {
      const WarningEntry& e = h.warnings.at(static_cast<WarningKind>(k));
      if (e.count == 0) continue;
      warnings[WarningName(static_cast<WarningKind>(k))] = {
          {"count", e.count}, {"first_time_s", e.first_time}, {"detail", e.detail}};
    }
    total += h.warnings.total();
    conditions.push_back({{"condition", run.conditions[c].name},
                          {"cycles", h.cycles},
                          {"numerical_failures", h.numerical_failures},
                          {"max_penetration_m", h.max_penetration},
                          {"penetration_bound_m", h.bound},
                          {"deepest_part", h.part},
                          {"warnings", warnings}});
  }
  return {{"conditions", conditions}, {"warnings", total}};
}

std::string HealthMarkdown(const experiment::DesignRun& run) {
  MarkdownTable md({"condition", "cycles", "numerical failures", "nearest its bound",
                    "deepest contact (um)", "bound (um)", "warnings"});
  const std::vector<ConditionHealth> health = Collect(run);
  for (std::size_t c = 0; c < health.size(); ++c) {
    const ConditionHealth& h = health[c];
    std::string warnings;
    for (int k = 0; k < kWarningKinds; ++k) {
      const WarningEntry& e = h.warnings.at(static_cast<WarningKind>(k));
      if (e.count == 0) continue;
      warnings += fmt::format("{}{} {}", warnings.empty() ? "" : ", ",
                              WarningName(static_cast<WarningKind>(k)), e.count);
    }
    md.AddRow({run.conditions[c].name, fmt::format("{}", h.cycles),
               fmt::format("{}", h.numerical_failures), h.part.empty() ? "-" : h.part,
               fmt::format("{:.3g}", h.max_penetration * 1e6),
               h.bound > 0 ? fmt::format("{:.3g}", h.bound * 1e6) : "-",
               warnings.empty() ? "none" : warnings});
  }
  return "\n### Numerical health\n\nPer condition: cycles ended by a numerical failure "
         "(left out of success rates), the part trial that came nearest its penetration "
         "bound (a tenth of its part's smallest radial clearance): its part, its deepest "
         "contact and its bound, and the warnings of every accepted step (counts; the "
         "first occurrence is in summary.json).\n\n" +
         ToMarkdown(md);
}

}  // namespace vahf::report
