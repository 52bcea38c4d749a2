#include "vahf/sim/internal/cvode_stepper.h"

#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "vahf/core/error.h"
#include "vahf/sim/internal/decisions.h"
#include "vahf/sim/internal/step_checks.h"
#include "vahf/sim/rigid_body.h"
#include "vahf/sim/rigid_body_jacobian.h"

namespace vahf::sim::internal {
namespace {

// The most one accepted step may deepen the contact, as a fraction of the
// hardening barrier's depth b (contact_params.h). A quarter: the barrier's
// factor (1 - x / b)^-2 is under 1.8 over it, so a step within it has met
// the law's gentle part, and a step past it has jumped to where the
// stiffness climbs without bound.
constexpr double kDeepeningLimit = 0.25;

// What CVODE's callbacks see.
struct Problem {
  TrialContext* c = nullptr;
  Decision held;
  std::string last_error;  // CVODE's last message, for the failure's detail
};

Eigen::Map<BodyState> Of(N_Vector v) {
  return Eigen::Map<BodyState>(N_VGetArrayPointer(v));
}

int Rhs(realtype, N_Vector y, N_Vector ydot, void* data) {
  Problem& p = *static_cast<Problem*>(data);
  const BodyState state = Of(y);
  const contact::RigidMotion m = MotionOf(state);
  if (!IsFinite(m)) return 1;  // recoverable: CVODE retries with a smaller step
  const Loads loads = p.c->LoadsAt(m, p.held);
  Of(ydot) = Derivative(p.c->model, state, loads, p.c->model.scene->gravity);
  return 0;
}

// The analytic Jacobian (rigid_body_jacobian.h) from one contact pass with
// its derivative, instead of CVODE's 13 difference quotients.
int Jacobian(realtype, N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector,
             N_Vector) {
  Problem& p = *static_cast<Problem*>(data);
  const PhaseTimer timer(p.c->Timing(&PhaseSeconds::jacobian));
  const BodyState state = Of(y);
  const contact::RigidMotion m = MotionOf(state);
  if (!IsFinite(m)) return 1;  // recoverable, as in Rhs
  LoadJacobian dloads;
  const Loads loads = p.c->model.LoadsAt(m, p.held, &p.c->contact_counters, &dloads);
  const BodyJacobian jacobian =
      DerivativeJacobian(p.c->model, state, loads, dloads, p.c->model.scene->gravity);
  for (int j = 0; j < kBodyStateSize; ++j)
    for (int i = 0; i < kBodyStateSize; ++i) SM_ELEMENT_D(J, i, j) = jacobian(i, j);
  return 0;
}

// The completion witness (as simbody_trial.cc's trigger): falls through zero
// when the part is within both thresholds.
int Root(realtype, N_Vector y, realtype* g, void* data) {
  const Problem& p = *static_cast<const Problem*>(data);
  const contact::RigidMotion m = MotionOf(Of(y));
  const auto& sim = p.c->params().simulation;
  g[0] = std::max(p.c->model.DistanceToTarget(m) / sim.completion_distance,
                  p.c->model.AngleToTargetDeg(m) / sim.completion_angle_deg) -
         1.0;
  return 0;
}

void OnError(int, const char* module, const char* function, char* message, void* data) {
  static_cast<Problem*>(data)->last_error =
      fmt::format("{} {}: {}", module, function, message);
}

// SUNDIALS objects, freed in reverse order of creation.
struct Cvode {
  SUNContext context = nullptr;
  N_Vector y = nullptr, dky = nullptr, atol = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  void* mem = nullptr;
  ~Cvode() {
    if (mem) CVodeFree(&mem);
    if (solver) SUNLinSolFree(solver);
    if (matrix) SUNMatDestroy(matrix);
    for (N_Vector v : {atol, dky, y})
      if (v) N_VDestroy(v);
    if (context) SUNContext_Free(&context);
  }
};

// CVODE's dense linear solver with its factorisations and solves timed
// (TrialOptions::time_phases): a linear solver of our own whose content is
// the dense one and the accumulator, every operation passed on to it.
struct TimedSolver {
  SUNLinearSolver dense;
  double* seconds;
};
SUNLinearSolver DenseOf(SUNLinearSolver s) {
  return static_cast<TimedSolver*>(s->content)->dense;
}
SUNLinearSolver TimedDense(SUNLinearSolver dense, double* seconds, SUNContext context) {
  SUNLinearSolver s = SUNLinSolNewEmpty(context);
  VAHF_CHECK(s != nullptr, "SUNLinSolNewEmpty failed");
  s->content = new TimedSolver{dense, seconds};
  s->ops->gettype = [](SUNLinearSolver t) { return SUNLinSolGetType(DenseOf(t)); };
  s->ops->getid = [](SUNLinearSolver t) { return SUNLinSolGetID(DenseOf(t)); };
  s->ops->initialize = [](SUNLinearSolver t) { return SUNLinSolInitialize(DenseOf(t)); };
  s->ops->setup = [](SUNLinearSolver t, SUNMatrix a) {
    const PhaseTimer timer(static_cast<TimedSolver*>(t->content)->seconds);
    return SUNLinSolSetup(DenseOf(t), a);
  };
  s->ops->solve = [](SUNLinearSolver t, SUNMatrix a, N_Vector x, N_Vector b,
                     realtype tol) {
    const PhaseTimer timer(static_cast<TimedSolver*>(t->content)->seconds);
    return SUNLinSolSolve(DenseOf(t), a, x, b, tol);
  };
  s->ops->lastflag = [](SUNLinearSolver t) { return SUNLinSolLastFlag(DenseOf(t)); };
  s->ops->space = [](SUNLinearSolver t, long* real, long* integer) {
    return SUNLinSolSpace(DenseOf(t), real, integer);
  };
  s->ops->free = [](SUNLinearSolver t) {
    if (!t) return 0;
    auto* content = static_cast<TimedSolver*>(t->content);
    SUNLinSolFree(content->dense);
    delete content;
    t->content = nullptr;
    SUNLinSolFreeEmpty(t);
    return 0;
  };
  return s;
}

// The absolute tolerances, in the part's units: `accuracy` m for its
// origin's position and accuracy / time_scale m/s for its velocity
// (simulation/velocity_time_scale), and for its orientation and angular
// velocity the same over L, its bounding radius about the origin, so that
// an error counts as the displacement or speed it causes at the part's
// farthest point (a unit quaternion's components move by half the angle).
void SetAbsoluteTolerances(const TrialModel& model, double accuracy, double time_scale,
                           N_Vector atol) {
  const double length = model.bounding_radius > 0 ? model.bounding_radius : 1.0;
  Eigen::Map<BodyState> a = Of(atol);
  a.segment<3>(0).setConstant(accuracy);
  a.segment<4>(3).setConstant(accuracy / (2 * length));
  a.segment<3>(7).setConstant(accuracy / time_scale);
  a.segment<3>(10).setConstant(accuracy / (length * time_scale));
}

// How far a step from y0 to y1 moves the part's farthest point, about: the
// origin's displacement plus the radius times the turn (twice the
// quaternion's change).
double Travel(const BodyState& y0, const BodyState& y1, double radius) {
  return (y1.segment<3>(0) - y0.segment<3>(0)).norm() +
         2 * radius * (y1.segment<4>(3) - y0.segment<4>(3)).norm();
}

// The cubic Hermite interpolant at ts in [t0, t1] of states y0, y1 with
// slopes d0, d1: exact for cubics, and fixed by the step's two ends and slopes.
BodyState Hermite(double t0, const BodyState& y0, const BodyState& d0, double t1,
                  const BodyState& y1, const BodyState& d1, double ts) {
  const double h = t1 - t0;
  if (!(h > 0)) return y1;
  const double s = (ts - t0) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 +
         (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * d1;
}

}  // namespace

double IntegrateWithCvode(TrialContext& c, double sample_interval,
                          std::optional<TraceRow>* final_row, TrialCounters* counters) {
  const auto& sim = c.params().simulation;
  const TrialModel& model = c.model;
  contact::RigidMotion start;
  start.pose = model.part->initial.Transform();
  const std::optional<Decision> first = Decide(c, 0.0, start);
  if (c.ended || !first) {  // ended at the first decision
    *final_row = FinalRow(c, 0.0, start);
    return 0.0;
  }
  Problem p;
  p.c = &c;
  p.held = *first;
  {
    Cvode cv;
    const auto ok = [&](int flag, const char* what) {
      VAHF_CHECK(flag >= 0, std::string("CVODE set-up failed: ") + what);
    };
    ok(SUNContext_Create(nullptr, &cv.context), "context");
    cv.y = N_VNew_Serial(kBodyStateSize, cv.context);
    cv.dky = N_VNew_Serial(kBodyStateSize, cv.context);
    Of(cv.y) = StateOf(start);
    cv.mem = CVodeCreate(CV_BDF, cv.context);
    VAHF_CHECK(cv.mem != nullptr, "CVodeCreate failed");
    ok(CVodeInit(cv.mem, Rhs, 0.0, cv.y), "init");
    ok(CVodeSetUserData(cv.mem, &p), "user data");
    ok(CVodeSetErrHandlerFn(cv.mem, OnError, &p), "error handler");
    cv.atol = N_VNew_Serial(kBodyStateSize, cv.context);
    SetAbsoluteTolerances(model, sim.accuracy, sim.velocity_time_scale, cv.atol);
    ok(CVodeSVtolerances(cv.mem, sim.accuracy, cv.atol), "tolerances");
    cv.matrix = SUNDenseMatrix(kBodyStateSize, kBodyStateSize, cv.context);
    cv.solver = SUNLinSol_Dense(cv.y, cv.matrix, cv.context);
    if (c.time_phases)
      cv.solver =
          TimedDense(cv.solver, c.Timing(&PhaseSeconds::linear_algebra), cv.context);
    ok(CVodeSetLinearSolver(cv.mem, cv.solver, cv.matrix), "linear solver");
    if (!c.difference_quotient_jacobian) ok(CVodeSetJacFn(cv.mem, Jacobian), "Jacobian");
    ok(CVodeRootInit(cv.mem, 1, Root), "root");
    int falling = -1;
    ok(CVodeSetRootDirection(cv.mem, &falling), "root direction");
    ok(CVodeSetMaxNumSteps(cv.mem, 1000000), "step limit");
    ok(CVodeSetMaxOrd(cv.mem, sim.max_order), "maximum order");
    ok(CVodeSetJacEvalFrequency(cv.mem, sim.jacobian_interval), "Jacobian interval");
    c.integrated = true;

    // CVODE's counters restart with it: the totals of the runs before.
    TrialCounters done;
    long run_conv_fails = 0;
    const auto harvest = [&] {
      long steps = 0, error_fails = 0, conv_fails = 0, rhs = 0, jac_rhs = 0,
           jacobians = 0;
      CVodeGetNumSteps(cv.mem, &steps);
      CVodeGetNumJacEvals(cv.mem, &jacobians);
      CVodeGetNumErrTestFails(cv.mem, &error_fails);
      CVodeGetNumNonlinSolvConvFails(cv.mem, &conv_fails);
      CVodeGetNumRhsEvals(cv.mem, &rhs);
      CVodeGetNumLinRhsEvals(cv.mem, &jac_rhs);
      done.steps_taken += steps;
      done.steps_attempted += steps + error_fails + conv_fails;
      done.error_test_failures += error_fails;
      done.realizations += rhs + jac_rhs;
      done.jacobian_evaluations += jacobians;
      run_conv_fails += conv_fails;
    };
    StepChecks checks(c);
    const double limit = sim.time_limit, interval = sim.decision_interval;
    std::int64_t next_sample = 1;
    double t = 0;
    // The last step kept, for a step taken back (below).
    BodyState kept_y = Of(cv.y);
    double kept_t = 0, kept_depth = 0;
    bool step_capped = false;
    // Its slope, once a step from it has been taken since a (re)start.
    BodyState kept_slope = BodyState::Zero();
    bool kept_slope_known = false;
    const double deepening_limit = kDeepeningLimit * model.contact.barrier_depth;
    for (std::int64_t i = 1; !c.ended && t < limit; ++i) {
      const double stop = std::min(static_cast<double>(i) * interval, limit);
      ok(CVodeSetStopTime(cv.mem, stop), "stop time");
      checks.Restarted();
      int flag = CV_SUCCESS;
      while (!c.ended) {
        flag = CVode(cv.mem, stop, cv.y, &t, CV_ONE_STEP);
        if (flag < 0) {
          c.ended = Status::kNumericalFailure;
          c.detail = fmt::format("CVODE stopped at t = {} s (flag {}): {}", t, flag,
                                 p.last_error);
          c.warnings.Note(WarningKind::kIntegratorFailure, t, c.detail);
          break;
        }
        // The accepted step: its checks, then the samples it covers.
        const BodyState y = Of(cv.y);
        const contact::RigidMotion m = MotionOf(y);
        // The depth check needs the contact alone, not the operator's load.
        const double depth = IsFinite(m) ? c.ContactAt(m).max_depth : 0.0;
        long conv_fails = 0;
        CVodeGetNumNonlinSolvConvFails(cv.mem, &conv_fails);
        const long retries = run_conv_fails + conv_fails;
        double h = 0;
        CVodeGetLastStep(cv.mem, &h);
        // The step's two ends and their slopes (CVODE's, at each end): its
        // cubic Hermite is the path checked and sampled below, when either
        // is asked for.
        BodyState slope = BodyState::Zero();
        if (deepening_limit > 0 || sample_interval > 0) {
          CVodeGetDky(cv.mem, t, 1, cv.dky);
          slope = Of(cv.dky);
          if (!kept_slope_known) {  // the first step since a (re)start
            CVodeGetDky(cv.mem, kept_t, 1, cv.dky);
            kept_slope = Of(cv.dky);
            kept_slope_known = true;
          }
        }
        const auto path = [&](double ts) {
          BodyState ys = Hermite(kept_t, kept_y, kept_slope, t, y, slope, ts);
          NormaliseQuaternion(&ys);
          return MotionOf(ys);
        };
        // A step that carries the contact deeper than kDeepeningLimit of the
        // barrier has jumped the contact's onset: CVODE's error test, in
        // units of position, cannot see micrometres, and the state it
        // accepted lies in the barrier's steep part, where the next steps'
        // corrector fails (docs/physics.md, Integrators). So has a step whose
        // path passes through a contact that neither end touches (the peg's
        // rim grazing the bore's chamfer within one step, 14 um deep between
        // clear ends): its midpoint is checked whenever the step moves the
        // part's farthest point by more than the limit, which no step in
        // contact does. Either is taken back and retaken with a quarter of
        // the step; the depth is continuous in time, so the retakes end. Not
        // below the step floor.
        bool retake = false;
        if (deepening_limit > 0 && h > sim.step_floor) {
          retake = depth - kept_depth > deepening_limit;
          if (!retake && Travel(kept_y, y, model.bounding_radius) > deepening_limit) {
            const contact::RigidMotion mid = path(kept_t + 0.5 * (t - kept_t));
            retake = IsFinite(mid) &&
                     c.ContactAt(mid).max_depth - std::max(depth, kept_depth) >
                         deepening_limit;
          }
        }
        if (retake) {
          harvest();
          --done.steps_taken;  // attempted, not taken
          Of(cv.y) = kept_y;
          t = kept_t;
          ok(CVodeReInit(cv.mem, t, cv.y), "retake");
          ok(CVodeSetStopTime(cv.mem, stop), "stop time");
          ok(CVodeSetMaxStep(cv.mem, 0.25 * h), "retake step");
          step_capped = true;
          checks.Restarted();
          continue;
        }
        if (step_capped) {  // the retaken step passed: CVODE chooses again
          ok(CVodeSetMaxStep(cv.mem, 0.0), "step cap lifted");
          step_capped = false;
        }
        if (!checks.Accepted(t, m, depth, h, retries, [&] {
              return fmt::format("{} nonlinear convergence failures", retries);
            }))
          break;
        // Samples in (before, t] on the same Hermite path, the one checked
        // above, rather than CVODE's own interpolant, a polynomial that also
        // carries the steps before this one.
        for (; sample_interval > 0; ++next_sample) {
          const double ts = static_cast<double>(next_sample) * sample_interval;
          if (ts > t || ts >= limit) break;
          const contact::RigidMotion ms = path(ts);
          c.samples.push_back(c.SampleRow(ts, ms, c.LoadsAt(ms, p.held), p.held.psi));
        }
        kept_y = y, kept_t = t, kept_depth = depth, kept_slope = slope;
        if (flag == CV_ROOT_RETURN) {
          c.ended = Status::kCompleted;
          c.completion_time = t;
          c.completion_row = FinalRow(c, t, m);  // Table 1's instant d, at this state
          c.detail = fmt::format("within {} m and {} deg of the target",
                                 sim.completion_distance, sim.completion_angle_deg);
        }
        if (flag == CV_TSTOP_RETURN || t >= stop) break;
      }
      if (c.ended || t >= limit) break;
      // The decision at t_i: what the operator holds from now on; the
      // right-hand side changed, so CVODE restarts from this state.
      BodyState y = Of(cv.y);
      NormaliseQuaternion(&y);
      Of(cv.y) = y;
      if (const std::optional<Decision> d = Decide(c, t, MotionOf(y))) p.held = *d;
      if (c.ended) break;
      harvest();
      ok(CVodeReInit(cv.mem, t, cv.y), "restart");
      kept_y = y, kept_t = t, kept_slope_known = false;
    }
    harvest();
    counters->steps_taken = done.steps_taken;
    counters->steps_attempted = done.steps_attempted;
    counters->error_test_failures = done.error_test_failures;
    counters->realizations = done.realizations;
    counters->jacobian_evaluations = done.jacobian_evaluations;
    counters->convergence_failures = run_conv_fails;
    if (c.completion_row)
      *final_row = c.completion_row;
    else
      *final_row = FinalRow(c, t, MotionOf(Of(cv.y)));
    return t;
  }
}

}  // namespace vahf::sim::internal
