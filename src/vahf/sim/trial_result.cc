#include "vahf/sim/trial_result.h"

#include <fmt/format.h>

#include <algorithm>

namespace vahf::sim {

const char* StatusName(Status status) {
  switch (status) {
    case Status::kCompleted:
      return "completed";
    case Status::kTimeout:
      return "timeout";
    case Status::kExhausted:
      return "exhausted";
    case Status::kUnreachable:
      return "unreachable";
    case Status::kJammed:
      return "jammed";
    case Status::kNumericalFailure:
      return "numerical_failure";
    case Status::kStepBudget:
      return "step_budget";
  }
  return "?";
}

void RestSummary::Add(double duration) {
  ++count;
  total_time += duration;
  longest = std::max(longest, duration);
}

bool IsComputationFailure(Status status) {
  return status == Status::kNumericalFailure || status == Status::kStepBudget;
}

std::string TrialResult::BriefReport() const {
  const TrialCounters& c = counters;
  std::string out = fmt::format("status: {} ({})\n", StatusName(status), detail);
  out += fmt::format("part: {}, seed {}, trial {}\n", part, key.seed, key.trial);
  if (status == Status::kCompleted)
    out += fmt::format("completion time: {:.6f} s\n", completion_time);
  out += fmt::format(
      "simulated: {:.6f} s in {:.4f} s wall, {:.4f} s CPU ({:.1f} x real time)\n",
      end_time, wall_seconds, cpu_seconds,
      cpu_seconds > 0 ? end_time / cpu_seconds : 0.0);
  out += fmt::format(
      "integrator: {} at accuracy {:g}: {} steps taken, {} attempted, {} error-test "
      "failures, {} realizations\n",
      integrator, accuracy, c.steps_taken, c.steps_attempted, c.error_test_failures,
      c.realizations);
  if (c.jacobian_evaluations > 0)
    out += fmt::format(
        "linear solver: {} Jacobian evaluations, {} nonlinear convergence failures\n",
        c.jacobian_evaluations, c.convergence_failures);
  out += fmt::format(
      "contact: {} shell points, {} evaluations, {} point queries, {} tests, {} clusters "
      "and {} pairs skipped by the broad phase\n",
      c.shell_points, c.contact_evaluations, c.contact_point_queries, c.contact_tests,
      c.clusters_skipped, c.broad_phase_skips);
  out += fmt::format("decisions: {}, rays cast: {}\n", c.decisions, c.rays_cast);
  if (penetration_bound > 0)
    out += fmt::format(
        "penetration: deepest {:.3g} um, bound {:.3g} um ({:.3g} um radial clearance)\n",
        max_penetration * 1e6, penetration_bound * 1e6, clearance * 1e6);
  else
    out += fmt::format("penetration: deepest {:.3g} um (no radial fit to bound it)\n",
                       max_penetration * 1e6);
  if (line_stiffness > 0)
    out += fmt::format("contact stiffness: {:.3g} Pa/m (faces), {:.3g} Pa (edges)\n",
                       stiffness, line_stiffness);
  else if (stiffness > 0)
    out += fmt::format("contact stiffness: {:.3g} Pa/m (faces)\n", stiffness);
  out += fmt::format("rests (simulation/rest_speed, rest_time): {}", rests.count);
  if (rests.count > 0)
    out += fmt::format(", {:.6g} s in all, the longest {:.6g} s", rests.total_time,
                       rests.longest);
  if (rests.withdrawals > 0)
    out += fmt::format("; withdrawals (guidance/stall_time): {}", rests.withdrawals);
  out += "\n";
  out += fmt::format("warnings: {}\n", warnings.Summary());
  return out;
}

}  // namespace vahf::sim
