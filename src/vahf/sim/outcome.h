// The checks that end a trial at a decision instant other than completion
// (docs/design.md decision 10): an unusable state (non-finite, or diverging), the
// operator exhausted (Eq. 6 at its floor), the part out of reach (beyond D3)
// and a jam (in contact without progress). Pure functions of what the decision
// measured, so each rule is tested without a simulation.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "vahf/contact/contact_model.h"
#include "vahf/scene/parameters.h"
#include "vahf/sim/trial_result.h"

namespace vahf::sim {

struct Ending {
  Status status;
  std::string detail;  // the measured values and the rule, for the trial's record
};

// kNumericalFailure if the pose or velocities hold a non-finite value, or if a
// point of the part's bounding sphere (radius `bounding_radius` about the
// origin of m) may move faster than divergence_speed. `where` and `decision`
// ("decision" 3, "a step after decision" 3) and `time` name the instant in
// the detail; nothing is formatted unless the state is unusable.
std::optional<Ending> CheckState(const contact::RigidMotion& m, double bounding_radius,
                                 const scene::SimulationParams& sim, const char* where,
                                 std::int64_t decision, double time);

// Progress towards the target, for the jam rule: a decision makes progress
// when it is the first, when the part is out of contact, or when it is
// jam_progress closer than the best distance so far. After the operator
// withdrew the part (guidance/stall_time) being out of contact is not
// progress until the part is jam_progress closer than its best again: a part
// withdrawn and stopped again and again, getting no deeper, is jammed.
class ProgressWatch {
 public:
  void Observe(bool first, double time, double distance, bool in_contact,
               double jam_progress);
  void Withdrew() { withdrawn_ = true; }
  double last_progress_time() const { return last_progress_time_; }

 private:
  double best_distance_ = 0;
  double last_progress_time_ = 0;
  bool withdrawn_ = false;
};

// What a decision measured, for CheckOperator.
struct DecisionFacts {
  double time = 0;               // s
  bool operator_acts = true;     // an operator guides the part (guidance mode not none)
  double psi = 1;                // Psi_c, Eq. 6
  double work = 0;               // A, J (Eq. 4)
  double shoulder_distance = 0;  // m
  double reach_limit = 0;        // D3, m
  bool in_contact = false;
  double distance = 0;  // from the part's origin to its target, m
};

// In order of precedence: exhausted (psi <= psi_floor), unreachable (beyond
// D3), both only when an operator acts; then jammed (in contact and no
// progress for jam_time since `progress`'s last progress).
std::optional<Ending> CheckOperator(const DecisionFacts& facts,
                                    const human::FatigueParams& fatigue,
                                    const scene::SimulationParams& sim,
                                    const ProgressWatch& progress);

}  // namespace vahf::sim
