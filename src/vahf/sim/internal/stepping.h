// Stepping one trial through Simbody (docs/design.md decisions 11-12): the
// loop of SimTK::TimeStepper, returning at every accepted step to check the
// state (finite, not diverging, contact within the penetration bound, step
// above the floor, retries counted) and to interpolate dense samples.
#pragma once

#include <Simbody.h>

#include "vahf/sim/internal/simbody_trial.h"

namespace vahf::sim::internal {

// Steps `integ` from t's initial state to completion, an ending or the
// scene's time limit, dispatching the system's scheduled and triggered events;
// with sample_interval > 0 it adds a dense trace row (samples) at every multiple
// of it, interpolated between accepted steps so that no integrator ever sees
// a sample time. Returns the time reached. Integrator exceptions propagate.
double Integrate(SimbodyTrial& t, SimTK::Integrator& integ, double sample_interval);

}  // namespace vahf::sim::internal
