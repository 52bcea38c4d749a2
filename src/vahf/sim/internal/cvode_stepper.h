// A stiff stepper for the free part without Simbody (docs/design.md decisions
// 11 and 13): SUNDIALS CVODE (variable-order BDF, Newton iteration, dense
// direct linear solver; A. C. Hindmarsh et al., ACM TOMS 31(3) 363, 2005) on
// the body's equations of motion (rigid_body.h) under the trial model's loads.
// Integrator name "CVODE", a core of the shared driver (stepper_driver.h),
// which restarts it at every t_i, checks every accepted step and samples on
// each step's path, so sampling never changes the trajectory; completion is
// CVODE's root finding on the completion witness.
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

#include <memory>

#include "vahf/sim/stepper_core.h"

namespace vahf::sim::internal {

// CVODE's core for the shared driver (stepper_driver.h), started at t = 0
// from `start`: it finds completion with CVODE's root finding, and sets the
// integrator's counters, CVODE's restarts included.
std::unique_ptr<StepperCore> MakeCvodeCore(RightHandSide& rhs, const BodyState& start);

}  // namespace vahf::sim::internal
