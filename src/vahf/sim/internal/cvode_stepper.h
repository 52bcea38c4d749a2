// A stiff stepper for the free part without Simbody (docs/design.md decisions
// 11 and 13): SUNDIALS CVODE (variable-order BDF, Newton iteration, dense
// direct linear solver; A. C. Hindmarsh et al., ACM TOMS 31(3) 363, 2005) on
// the body's equations of motion (rigid_body.h) under the trial model's loads.
// Integrator name "CVODE". The decisions restart it at every t_i, completion
// is CVODE's root finding on the completion witness, every accepted step is
// checked (step_checks.h), and dense samples come from CVODE's own
// interpolant, so sampling never changes the trajectory.
//
// Tolerances: relative `accuracy`; absolute `accuracy` in m and m/s for the
// origin's position and velocity, and for the orientation and angular
// velocity `accuracy` / L (the quaternion's: half that), L the part's
// bounding radius about its origin: an error counts as the displacement or
// speed it causes at the part's farthest point. (Simbody's default unit
// weights count 1 rad as 1 m, which for a 50 mm peg asks 20 times more of
// its angular velocity than of its rim's speed; the step was then held by
// the error estimates of wx and wy.) The Jacobian is analytic
// (rigid_body_jacobian.h: one contact pass with its derivative, instead of the
// 13 right-hand sides of CVODE's difference quotient, which
// TrialContext::difference_quotient_jacobian restores for comparison).
#pragma once

#include <optional>

#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/trial_result.h"

namespace vahf::sim::internal {

// Makes the decision at t = 0 and steps c's trial to completion, an ending or
// the time limit. Returns the time reached; sets *final_row and the
// integrator's counters. Numerical trouble ends the trial as a numerical
// failure with a detail, never an exception.
double IntegrateWithCvode(TrialContext& c, double sample_interval,
                          std::optional<TraceRow>* final_row, TrialCounters* counters);

}  // namespace vahf::sim::internal
