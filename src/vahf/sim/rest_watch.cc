#include "vahf/sim/rest_watch.h"

#include <fmt/format.h>

#include <cmath>

namespace vahf::sim {

std::string Rest::Detail() const {
  return fmt::format(
      "{:.6g} s from t = {:.6g} s at T = ({:.6g}, {:.6g}, {:.6g}) m, "
      "{:.6g} m from the target",
      duration, start, position.x(), position.y(), position.z(), distance);
}

std::optional<Rest> RestWatch::Observe(std::int64_t decision,
                                       const Eigen::Vector3d& position, double distance,
                                       bool in_contact,
                                       const scene::SimulationParams& sim) {
  std::optional<Rest> ended;
  if (last_decision_ >= 0 && decision > last_decision_) {
    // The interval since the last decision: in contact at both ends and the
    // distance to the target changed slower than rest_speed on average.
    const double elapsed =
        static_cast<double>(decision - last_decision_) * sim.decision_interval;
    const bool resting = in_contact && last_in_contact_ &&
                         std::abs(distance - last_distance_) < sim.rest_speed * elapsed;
    if (resting && rest_start_ < 0) {
      rest_start_ = last_decision_;
      rest_position_ = last_position_;
      rest_distance_ = last_distance_;
    } else if (!resting) {
      ended = End(sim);
    }
  }
  last_decision_ = decision;
  last_position_ = position;
  last_distance_ = distance;
  last_in_contact_ = in_contact;
  return ended;
}

double RestWatch::OpenRest(double decision_interval) const {
  if (rest_start_ < 0) return 0;
  return static_cast<double>(last_decision_ - rest_start_) * decision_interval;
}

std::optional<Rest> RestWatch::Close(const scene::SimulationParams& sim) {
  return End(sim);
}

// The rest open from rest_start_ to last_decision_, if it counts.
std::optional<Rest> RestWatch::End(const scene::SimulationParams& sim) {
  if (rest_start_ < 0) return std::nullopt;
  Rest rest;
  // From the decisions' indices, so that one interval lasts decision_interval
  // exactly (t_i - t_{i-1} need not).
  rest.start = static_cast<double>(rest_start_) * sim.decision_interval;
  rest.duration =
      static_cast<double>(last_decision_ - rest_start_) * sim.decision_interval;
  rest.position = rest_position_;
  rest.distance = rest_distance_;
  rest_start_ = -1;
  if (rest.duration < sim.rest_time) return std::nullopt;
  summary_.Add(rest.duration);
  return rest;
}

}  // namespace vahf::sim
