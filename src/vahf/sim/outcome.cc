#include "vahf/sim/outcome.h"

#include <fmt/format.h>

#include <cmath>

#include "vahf/human/fatigue.h"

namespace vahf::sim {

std::optional<Ending> CheckState(const contact::RigidMotion& m, double bounding_radius,
                                 const scene::SimulationParams& sim, const char* where,
                                 std::int64_t decision, double time) {
  const Eigen::Vector3d T = m.pose.translation();
  if (!T.allFinite() || !m.velocity.allFinite() || !m.angular_velocity.allFinite() ||
      !m.pose.linear().allFinite()) {
    return Ending{
        Status::kNumericalFailure,
        fmt::format("non-finite state at {} {} (t = {} s)", where, decision, time)};
  }
  // The fastest point of the part's bounding sphere, a bound on any point's speed.
  const double speed = m.velocity.norm() + m.angular_velocity.norm() * bounding_radius;
  if (speed > sim.divergence_speed) {
    return Ending{
        Status::kNumericalFailure,
        fmt::format("diverged: a point of the part moves at up to {:.6g} m/s > "
                    "divergence_speed {} m/s at {} {} (t = {} s, position {:.6g} "
                    "{:.6g} {:.6g} m)",
                    speed, sim.divergence_speed, where, decision, time, T.x(), T.y(),
                    T.z())};
  }
  return std::nullopt;
}

void ProgressWatch::Observe(bool first, double time, double distance, bool in_contact,
                            double jam_progress) {
  const bool nearer = best_distance_ - distance >= jam_progress;
  if (nearer) withdrawn_ = false;
  if (first || nearer || (!in_contact && !withdrawn_)) {
    if (first || distance < best_distance_) best_distance_ = distance;
    last_progress_time_ = time;
  }
}

std::optional<Ending> CheckOperator(const DecisionFacts& facts,
                                    const human::FatigueParams& fatigue,
                                    const scene::SimulationParams& sim,
                                    const ProgressWatch& progress) {
  if (facts.operator_acts && human::IsExhausted(facts.psi, fatigue.psi_floor)) {
    return Ending{Status::kExhausted,
                  fmt::format("Psi_c = {:.4f} <= floor {} at t = {} s (A = {:.6g} J)",
                              facts.psi, fatigue.psi_floor, facts.time, facts.work)};
  }
  if (facts.operator_acts && facts.shoulder_distance > facts.reach_limit) {
    return Ending{Status::kUnreachable,
                  fmt::format("shoulder distance {:.4f} m > D3 = {:.4f} m at t = {} s",
                              facts.shoulder_distance, facts.reach_limit, facts.time)};
  }
  if (facts.in_contact && facts.time - progress.last_progress_time() >= sim.jam_time) {
    return Ending{
        Status::kJammed,
        fmt::format("in contact without {} m of progress since t = {} s; "
                    "{:.6f} m from the target",
                    sim.jam_progress, progress.last_progress_time(), facts.distance)};
  }
  return std::nullopt;
}

}  // namespace vahf::sim
