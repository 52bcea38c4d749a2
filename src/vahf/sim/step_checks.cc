#include "vahf/sim/internal/step_checks.h"

#include <fmt/format.h>

#include <algorithm>

namespace vahf::sim::internal {

bool StepChecks::Accepted(double t, const contact::RigidMotion& m, double depth, double h,
                          std::int64_t retries,
                          const std::function<std::string()>& retry_detail) {
  if (std::optional<Ending> bad =
          CheckState(m, c_.model.bounding_radius, c_.params().simulation,
                     "a step after decision", c_.last_decision, t)) {
    if (!IsFinite(m)) c_.warnings.Note(WarningKind::kNonFiniteState, t, bad->detail);
    c_.End(std::move(*bad));
    return false;
  }
  Depth(depth, t);
  const int budget = c_.params().simulation.max_steps;
  if (++accepted_ >= budget) {
    c_.End({Status::kStepBudget,
            fmt::format("{} accepted steps (simulation/max_steps) at t = {} s, {} s of "
                        "simulated time a step on average",
                        accepted_, t, t / static_cast<double>(accepted_))});
    return false;
  }
  const std::uint64_t tests = c_.contact_counters.Tests();
  const double test_budget = c_.params().simulation.max_contact_tests;
  if (static_cast<double>(tests) >= test_budget) {
    c_.End(
        {Status::kStepBudget,
         fmt::format("{} contact tests (simulation/max_contact_tests {:g}) at t = {} s "
                     "after {} accepted steps, {:.0f} tests a step on average",
                     tests, test_budget, t, accepted_,
                     static_cast<double>(tests) / static_cast<double>(accepted_))});
    return false;
  }
  const double floor = c_.params().simulation.step_floor;
  if (++steps_since_restart_ > kProbingSteps && h > 0 && h < floor)
    c_.warnings.Count(WarningKind::kStepSizeFloor, t, [&] {
      return fmt::format("step {:.3g} s < floor {:.3g} s", h, floor);
    });
  if (retries > retries_)
    c_.warnings.Count(WarningKind::kIntegratorRetry, t, retry_detail, retries - retries_);
  retries_ = retries;
  return true;
}

// The deepest contact so far, and a warning past the bound.
void StepChecks::Depth(double depth, double t) {
  c_.max_penetration = std::max(c_.max_penetration, depth);
  const TrialModel& model = c_.model;
  if (model.penetration_bound > 0 && depth > model.penetration_bound)
    c_.warnings.Count(WarningKind::kPenetrationBound, t, [&] {
      return fmt::format(
          "depth {:.3g} um > bound {:.3g} um ({} of the {:.3g} um radial "
          "clearance)",
          depth * 1e6, model.penetration_bound * 1e6,
          c_.params().contact.penetration_fraction, model.clearance * 1e6);
    });
}

}  // namespace vahf::sim::internal
