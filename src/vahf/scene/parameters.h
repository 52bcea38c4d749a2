// Every model parameter a scene can set, grouped as in the scene file's
// "parameters" object. Defaults are the member initialisers; docs/parameters.md
// is generated from parameter_table.cc (`vahf params`) and tested against it.
#pragma once

#include <string>

#include "vahf/contact/contact_params.h"
#include "vahf/core/param_decl.h"
#include "vahf/guidance/assembly_force.h"
#include "vahf/human/factor_curves.h"
#include "vahf/human/fatigue.h"
#include "vahf/human/learning.h"
#include "vahf/visibility/visibility_params.h"

namespace vahf::scene {

// The operator's control loop and how a trial ends (docs/design.md decisions 1, 8).
struct SimulationParams {
  // Interval between the operator's decisions, s: human factors and the Eq. 5
  // draws are evaluated at t_i = i * decision_interval and held in between.
  // 0.1 s is of the order of the visual feedback delay of aimed hand movements
  // (Keele and Posner, J. Exp. Psychol. 77 (1968) 155-158: 190-260 ms; Elliott
  // et al., Psychol. Bull. 127 (2001) 342-357: about 100 ms).
  double decision_interval = 0.1;
  double time_limit = 30.0;           // s: status timeout past it
  double completion_distance = 1e-3;  // d_th of Sec. 3.1, m
  double completion_angle_deg = 2.0;  // angle to the target orientation, deg
  double jam_time = 2.0;              // s in contact without progress: jammed
  double jam_progress = 1e-4;         // m of approach that counts as progress
  // A rest (sim/rest_watch.h, docs/physics.md "Rests"): the part in contact at
  // consecutive decisions with its distance to the target changed by less
  // than rest_speed times the time between them, m/s. 1 mm/s is the compliant contact's
  // friction transition speed (contact/friction_transition_speed's default):
  // below it the regularised Coulomb law lets a part held inside its friction
  // cone creep, which Coulomb's law would hold still, so creeping slower than
  // it counts as resting (issue 53).
  double rest_speed = 1e-3;
  // The shortest rest counted, s: issue 53's 0.1 s, one decision interval.
  double rest_time = 0.1;
  // A point of the part moving faster than this, m/s, means the integration
  // diverged (status numerical_failure): hand-guided parts move at a few m/s,
  // and a part dropped from a 1 m workbench lands at 4.4 m/s.
  double divergence_speed = 20.0;
  std::string integrator = "RungeKuttaMerson";
  double accuracy = 1e-4;  // integrator relative accuracy
  // The settings a stepper declares with its line in steppers.def
  // (fixed_step, velocity_time_scale, max_order, jacobian_interval), read
  // through scene::stepper_settings (stepper_catalogue.h).
  core::ParamValues stepper_values;
  // An accepted step shorter than this, s, is recorded as a warning
  // (step_size_floor): the integrator is resolving something far faster than
  // the contact oscillation (about 1e-4 s) or sticking friction (a few
  // microseconds) it is built for.
  double step_floor = 1e-8;
  // The work budget of a trial, in accepted integrator steps: a trial still
  // running after this many ends as status step_budget, a failure of the
  // computation like numerical_failure. Counted in steps, not seconds, so
  // that where a trial ends never depends on the machine. Each accepted step
  // costs a bounded number of attempts (CVODE: at most 7 error-test and 10
  // convergence failures a step; Simbody's integrators: down to their minimum
  // step) and every decision ends a step, so this bounds a trial's work. The
  // shipped scenes take at most about 3.3e4 steps a simulated second
  // (`vahf trial --seed 1`: peg_in_hole_resolved under CPodes, 6241 steps for
  // 0.188 s; the cylinder's rod under CVODE, 15 394 for 0.827 s), so 1e6
  // holds any of them for 30 s of simulated time.
  int max_steps = 1000000;
  // The other half of the work budget: the contact's elementary tests (point
  // and rim queries and the profile edges they examine, ContactCounters::
  // Tests). The step count alone does not bound a step's cost, which grows
  // with the points in contact and a profile's vertices: a 104-vertex
  // sawtooth peg wedged in its bore spends about 7 ms a step (tests/fuzz/
  // FINDINGS.md, mutant 48454). A trial past this many tests ends as status
  // step_budget too; counted, not timed, so that where it ends never depends
  // on the machine. The default is max_steps times the most tests a step of
  // any shipped configuration takes, so on those the step count ends a trial
  // first and only a far costlier step meets this budget. Measured with
  // `vahf trial --seed 1`: the cylinder's rod under the precision reference
  // (RungeKuttaMerson 1e-8) 28 500 tests a step (6.9e8 for 24 267 steps),
  // the peg's 18 900, the scenes' own settings 6600-8100; the wedged sawtooth
  // peg 1.1e6, which the budget ends after about 27 000 steps (200 s of CPU
  // at its 1.5e8 tests a CPU second).
  double max_contact_tests = 3e10;
};

struct Parameters {
  human::PlateauCurve sight = human::DefaultSightCurve();    // f, Fig. 3
  human::PlateauCurve glance = human::DefaultGlanceCurve();  // g, Fig. 5
  human::ReachCurve reach;                                   // r, Fig. 4
  human::FatigueParams fatigue;
  human::LearningParams learning;
  guidance::GuidanceParams guidance;
  contact::ContactParams contact;
  visibility::VisibilityParams visibility;
  SimulationParams simulation;
};

}  // namespace vahf::scene
