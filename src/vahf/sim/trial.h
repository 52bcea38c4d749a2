// One trial: the assembling part at one position of the scene's sequence,
// moved by gravity, contact and the simulated operator until it reaches its
// target or fails (paper Sec. 3.1, Fig. 2; DESIGN.md decisions 1-3, 6-10).
//
// The Simbody system holds only what the scene needs: the assembling part on
// a free mobilizer; gravity; one force element for the operator's force and
// torque and the penalty contact against the fixed parts (the base, parts with
// role "assembled", and the parts assembled earlier in the sequence, at their
// targets); no contact work at all when there is nothing to touch.
#pragma once

#include <string>

#include "vahf/rng/stream.h"
#include "vahf/scene/scene.h"
#include "vahf/sim/trial_result.h"

namespace vahf::sim {

struct TrialOptions {
  int sequence_position = 0;  // which entry of scene.sequence to assemble
  double initial_work = 0.0;  // A carried over from earlier work, J
  bool record_trace = true;
};

// Runs one trial with the integrator and accuracy of scene.params.simulation.
// Same scene, key and options: the same result bits (wall_seconds aside).
// With visibility mode "raycast", V (Eq. 1) is cast from the operator's eye
// at every decision, against the fixed parts; with nothing fixed no mesh is
// built and no ray is cast. Numerical trouble is a status, never an exception.
TrialResult RunTrial(const scene::Scene& scene, rng::StreamKey key,
                     const TrialOptions& options = {});

}  // namespace vahf::sim
