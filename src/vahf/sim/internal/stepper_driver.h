// The shared driver of the steppers of the trial model's own right-hand side
// (stepper_core.h; docs/design.md decision 13): one trial, stepped by a
// StepperCore from its first decision to completion, an ending or the time
// limit. It owns the decision at every t_i (the core Reset after each), the
// checks of every accepted step (step_checks.h), the take-back of a step
// that deepens the contact too far, the dense samples on each step's cubic
// Hermite path, completion (the core's root, or located on that path), the
// time limit, numerical failures as endings and the counters. Simbody's
// integrators keep their own driver (stepping.h).
#pragma once

#include <optional>

#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/stepper_core.h"
#include "vahf/sim/trial_result.h"

namespace vahf::sim::internal {

// How closely the driver locates completion for a core that does not find
// roots: the bisection on the step's path stops when its bracket is this
// short, s (a thousandth of the shortest step the checks accept quietly,
// simulation/step_floor's default 1e-8 s).
inline constexpr double kCompletionTolerance = 1e-11;

// Makes the decision at t = 0, starts the core `make` builds and steps c's
// trial to completion, an ending or the time limit. Returns the time
// reached; sets *final_row and the core's counters.
// Numerical trouble ends the trial as a numerical failure with a detail,
// never an exception.
double DriveTrial(TrialContext& c, CoreFactory make, double sample_interval,
                  std::optional<TraceRow>* final_row, TrialCounters* counters);

}  // namespace vahf::sim::internal
