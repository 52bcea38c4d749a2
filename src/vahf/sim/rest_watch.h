// The part's rests (issue 53, item 2; docs/physics.md, "Rests"): where a part
// in contact stops or creeps, the contact's friction law (its regularisation
// on the compliant path, exact stick on MoreauJean) rather than the operator
// decides how long it stays. A pure function of what the decisions measured,
// so every stepper counts rests alike and each rule is tested without a
// simulation.
//
// A rest is a run of consecutive decision intervals over each of which the
// part is in contact at both ends (a normal force at the decision) and its
// distance to the target (the part's origin T to its target, as completion
// and the jam rule measure it) changes by less than simulation/rest_speed
// times the interval, either way; it is counted when it lasts
// simulation/rest_time or longer. The progress speed, not a point's speed:
// a rod held at a mouth pivots about the rim under the operator's torque,
// its centre of mass swinging faster than it goes in, and what a rest costs
// is progress. Observed at the decision instants t_i = i * decision_interval
// alone: they are the same instants for every stepper and step size (a
// step's ends are not, and samples exist only when asked for, which must
// change no result), they cost nothing the decision does not compute
// already, and a change over an interval is a mean speed, not the chatter of
// one instant in contact. A rest's duration is a whole number of intervals.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>

#include "vahf/scene/parameters.h"
#include "vahf/sim/trial_result.h"

namespace vahf::sim {

// One rest of the part.
struct Rest {
  double start = 0;                                    // s: the decision instant it began
  double duration = 0;                                 // s: whole decision intervals
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // T at its start, world, m
  double distance = 0;  // from T to the target at its start, m

  // "0.8 s from t = 0.4 s at T = (x, y, z) m, 0.0521 m from the target"
  std::string Detail() const;
};

class RestWatch {
 public:
  // The part at decision `decision` (at decision * sim.decision_interval):
  // its origin T, T's distance to the target, whether it is in contact.
  // Returns the rest that this decision ended, when it lasted at least
  // sim.rest_time (it is in summary() too).
  std::optional<Rest> Observe(std::int64_t decision, const Eigen::Vector3d& position,
                              double distance, bool in_contact,
                              const scene::SimulationParams& sim);
  // The trial ended: the rest still open up to the last decision observed,
  // when it lasted at least sim.rest_time.
  std::optional<Rest> Close(const scene::SimulationParams& sim);

  // How long the part has rested up to the last decision observed, counted
  // or not yet (s, whole decision intervals); 0 when it is not resting.
  double OpenRest(double decision_interval) const;
  // The operator withdrew the part at the last decision observed
  // (guidance/stall_time): counted in summary().withdrawals.
  void Withdrew() { ++summary_.withdrawals; }

  const RestSummary& summary() const { return summary_; }

 private:
  std::optional<Rest> End(const scene::SimulationParams& sim);

  // The last decision observed (-1: none): where the part was, and whether
  // in contact there.
  std::int64_t last_decision_ = -1;
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  double last_distance_ = 0;
  bool last_in_contact_ = false;
  // The rest open from decision rest_start_ to the last (-1: none), its place.
  std::int64_t rest_start_ = -1;
  Eigen::Vector3d rest_position_ = Eigen::Vector3d::Zero();
  double rest_distance_ = 0;
  RestSummary summary_;
};

}  // namespace vahf::sim
