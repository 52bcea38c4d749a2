// What a stepper of the trial model's own right-hand side implements
// (kOwnRightHandSide in scene/steppers.def; docs/design.md decision 13): a
// StepperCore that takes one accepted step at a time. The shared driver
// (internal/stepper_driver.h) owns the rest of the trial: the decisions at
// every t_i and the core's Reset after each, the checks of every accepted
// step, the take-back of a step that deepens the contact too far, the dense
// samples, completion (located on the step's path for a core that does not
// find it itself), the time limit, failures as endings and the counters.
// A new stepper is a core, its factory and its line in steppers.def
// (docs/extending.md, "A stepper").
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "vahf/scene/parameters.h"
#include "vahf/sim/rigid_body.h"
#include "vahf/sim/trial_model.h"
#include "vahf/sim/trial_result.h"

namespace vahf::sim {
namespace internal {
struct TrialContext;
}  // namespace internal

// The trial model's right-hand side under the decision the operator holds,
// its contact counted on the trial's counters: what a core integrates.
class RightHandSide {
 public:
  explicit RightHandSide(internal::TrialContext& c) : c_(c) {}

  // dy/dt at y (rigid_body.h's Derivative under the held loads); false, and
  // dydt untouched, when y's motion is not finite.
  bool Derivative(const BodyState& y, BodyState* dydt);

  const TrialModel& model() const;
  const scene::SimulationParams& settings() const;  // the scene's simulation/ group
  const Decision& held() const { return held_; }
  void Hold(const Decision& d) { held_ = d; }
  // The trial, for a core inside sim (CVODE's Jacobian and timers).
  internal::TrialContext& context() { return c_; }

 private:
  internal::TrialContext& c_;
  Decision held_;
};

// What one call of StepperCore::StepTo did.
struct StepOutcome {
  enum Kind {
    kStepped,      // an accepted step, short of the stop time
    kReachedStop,  // an accepted step that ends at the stop time
    kCompleted,    // an accepted step that ends where the core found completion
    kFailed,       // no step: the core cannot go on (detail says why)
  };
  Kind kind = kStepped;
  double t = 0;              // the time reached
  double h = 0;              // the accepted step's size
  std::int64_t retries = 0;  // running total of failed attempts other than error tests
  std::string detail;        // kFailed: the core's words
};

class StepperCore {
 public:
  virtual ~StepperCore() = default;

  // Restarts at (t, y) under the right-hand side's new decision (after each
  // decision instant; the factory starts the core at t = 0).
  virtual void Reset(double t, const BodyState& y) = 0;
  // Back to the kept (t, y) after a step was taken back, the next steps at
  // most max_step until Kept.
  virtual void Retake(double t, const BodyState& y, double max_step) = 0;
  // The last step was kept (it passed the take-back check): a step cap of
  // Retake is lifted.
  virtual void Kept() {}
  // One accepted step toward `stop`, never past it.
  virtual StepOutcome StepTo(double stop) = 0;
  // The state at the end of the last step, and dy/dt at either end of it.
  virtual BodyState State() const = 0;
  virtual BodyState Slope(double t) = 0;
  // True when StepTo reports kCompleted itself (on the completion witness,
  // TrialModel::CompletionWitness, falling through zero); otherwise the
  // driver locates completion on each step's path.
  virtual bool FindsRoots() const { return false; }
  // How retries read in a step check's detail.
  virtual std::string RetryDetail(std::int64_t retries) const;
  // Sets the core's counters for the whole trial (steps taken and attempted,
  // error-test failures, right-hand side evaluations as realizations, ...),
  // once, when it has ended.
  virtual void SetCounters(TrialCounters* counters) = 0;
};

// A kOwnRightHandSide or kContactPoints stepper's factory: its core, started at t = 0
// from `start` with rhs under the first decision.
using CoreFactory = std::unique_ptr<StepperCore> (*)(RightHandSide& rhs,
                                                     const BodyState& start);

}  // namespace vahf::sim
