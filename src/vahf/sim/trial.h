// One trial: the assembling part at one position of the scene's sequence,
// moved by gravity, contact and the simulated operator until it reaches its
// target or fails (paper Sec. 3.1, Fig. 2; docs/design.md decisions 1-3, 6-10).
//
// The part's trial model (trial_model.h) is built once and shared: its
// contact model against the fixed parts (the base, parts with role
// "assembled", and the parts assembled earlier in the sequence, at their
// targets; no contact work at all when there is nothing to touch), its
// visibility meshes, its operator. Each trial builds its Simbody system
// (internal/simbody_trial.h): the part on a free mobilizer, gravity, and the model's
// contact and operator loads.
#pragma once

#include <string>

#include "vahf/rng/stream.h"
#include "vahf/scene/scene.h"
#include "vahf/sim/trial_model.h"
#include "vahf/sim/trial_result.h"

namespace vahf::sim {

struct TrialOptions {
  // Which entry of scene.sequence to assemble (the scene overload of RunTrial;
  // a TrialModel knows its own).
  int sequence_position = 0;
  double initial_work = 0.0;  // A carried over from earlier work, J
  bool record_trace = true;
  // > 0: also record a dense trace row every sample_interval seconds of
  // simulated time (TrialResult::samples), from the integrator's
  // interpolant: the trajectory and the result are the same as without.
  double sample_interval = 0.0;
  // CVODE only, for comparisons and tests: CVODE's difference-quotient
  // Jacobian (13 right-hand sides each) instead of the analytic one.
  bool difference_quotient_jacobian = false;
  // For tests and comparisons: a contact pass at every accepted step for its
  // checks, rather than the bound from the last pass where that settles them
  // (stepper_driver.cc, Drive::DepthAt). The same checks' decisions.
  bool depth_pass_every_step = false;
  // For benchmarks: measure where the time goes (TrialResult::phases,
  // phase_seconds.h). Changes no bit of the result.
  bool time_phases = false;
  // The operator's repetition of the task, from 1 (human/learning.h: with a
  // learning model, the n-th repetition's operator is practised).
  int repetition = 1;
};

// Runs one trial with the integrator and accuracy of scene.params.simulation.
// Same scene, key and options: the same result bits (wall_seconds aside).
// With visibility mode "raycast", V (Eq. 1) is cast from the operator's eye
// at every decision, against the fixed parts; with nothing fixed no mesh is
// built and no ray is cast. Numerical trouble is a status, never an exception,
// and every accepted step is checked (the warnings record: non-finite state,
// contact deeper than the penetration bound, a step under the floor, retries).
// Thread-safe: trials of one model run concurrently.
TrialResult RunTrial(const TrialModel& model, rng::StreamKey key,
                     const TrialOptions& options = {});
// Builds the model of the part at options.sequence_position, then runs it.
TrialResult RunTrial(const scene::Scene& scene, rng::StreamKey key,
                     const TrialOptions& options = {});

}  // namespace vahf::sim
