// The checks made at every accepted step of any stepper (docs/design.md
// decision 12), without Simbody: the state is finite and not diverging, the
// contact depth is within the penetration bound, the step is above the floor,
// the integrator's retries since the last step are counted, and the trial is
// within its work budget (simulation/max_steps accepted steps and
// max_contact_tests contact tests).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "vahf/contact/contact_model.h"
#include "vahf/sim/internal/trial_context.h"

namespace vahf::sim::internal {

class StepChecks {
 public:
  explicit StepChecks(TrialContext& c) : c_(c) {}

  // An accepted step to time t, of size h, ending at motion m with the
  // contact `depth` there; `retries` is the integrator's running total of
  // failed attempts other than error-test failures, `retry_detail` says what
  // they were. False when the state is unusable or the budget is spent (the
  // trial has ended).
  bool Accepted(double t, const contact::RigidMotion& m, double depth, double h,
                std::int64_t retries, const std::function<std::string()>& retry_detail);

  // The integrator restarted (initialization or an event handled): its first
  // steps probe the step size (CPodes begins near 1e-11 s), not a sign of
  // trouble, and are not held to the floor.
  void Restarted() { steps_since_restart_ = 0; }

 private:
  void Depth(double depth, double t);

  TrialContext& c_;
  std::int64_t retries_ = 0;
  std::int64_t accepted_ = 0;
  static constexpr int kProbingSteps = 3;
  int steps_since_restart_ = 0;
};

}  // namespace vahf::sim::internal
