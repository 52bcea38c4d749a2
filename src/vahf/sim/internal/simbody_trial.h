// A trial's Simbody model (docs/design.md decisions 1, 11 and 13): the moving
// body on a free mobilizer, gravity, one force element that applies the trial
// model's contact and operator loads (TrialModel::LoadsAt) with the held
// decision as a discrete variable, the decision instants as a periodic event
// and completion as a triggered one.
#pragma once

#include <Simbody.h>

#include "vahf/sim/internal/trial_context.h"

namespace vahf::sim::internal {

class SimbodyTrial {
 public:
  // Builds the system for c's model, at the part's initial pose, and makes
  // the decision at t = 0 (which may end the trial).
  explicit SimbodyTrial(TrialContext& c);
  SimbodyTrial(const SimbodyTrial&) = delete;
  SimbodyTrial& operator=(const SimbodyTrial&) = delete;

  TrialContext& context() { return c_; }
  const SimTK::MultibodySystem& system() const { return system_; }
  const SimTK::State& initial_state() const { return initial_; }

  // The part's pose (needs Stage::Position), with zero velocities.
  contact::RigidMotion PoseOf(const SimTK::State& s) const;
  // Pose and velocities (needs Stage::Velocity).
  contact::RigidMotion MotionOf(const SimTK::State& s) const;
  const Decision& HeldDecision(const SimTK::State& s) const;
  // The loads the force element computed at s (needs Stage::Dynamics).
  const Loads& LoadsOf(const SimTK::State& s) const;

  // The decision at s's time (decisions.h), held in s from now on.
  void Decide(SimTK::State& s);
  // decisions.h's FinalRow at s.
  TraceRow FinalRow(SimTK::State& s);

 private:
  class LoadsElement;
  class DecisionHandler;
  class CompletionTrigger;

  TrialContext& c_;
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  SimTK::MobilizedBodyIndex body_;
  SimTK::DiscreteVariableIndex decision_index_;
  SimTK::CacheEntryIndex loads_index_;
  SimTK::State initial_;
};

}  // namespace vahf::sim::internal
