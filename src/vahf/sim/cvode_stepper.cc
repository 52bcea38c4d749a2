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
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/internal/decisions.h"
#include "vahf/sim/internal/step_checks.h"
#include "vahf/sim/rigid_body.h"
#include "vahf/sim/rigid_body_jacobian.h"

namespace vahf::sim::internal {
namespace {

namespace stepper_settings = scene::stepper_settings;

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
  Of(ydot) = Derivative(p.c->model, state, loads, p.c->model.gravity);
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
      DerivativeJacobian(p.c->model, state, loads, dloads, p.c->model.gravity);
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

void Ok(int flag, const char* what) {
  VAHF_CHECK(flag >= 0, std::string("CVODE set-up failed: ") + what);
}

// CVODE set up for c's trial from the part's state `start`: BDF with
// Newton iteration, the dense linear solver (timed when c asks), the
// analytic Jacobian unless c asks for difference quotients, root finding on
// the completion witness, and the scene's order and Jacobian interval.
void SetUp(TrialContext& c, const contact::RigidMotion& start, Problem* p, Cvode* cv) {
  const auto& sim = c.params().simulation;
  Ok(SUNContext_Create(nullptr, &cv->context), "context");
  cv->y = N_VNew_Serial(kBodyStateSize, cv->context);
  cv->dky = N_VNew_Serial(kBodyStateSize, cv->context);
  Of(cv->y) = StateOf(start);
  cv->mem = CVodeCreate(CV_BDF, cv->context);
  VAHF_CHECK(cv->mem != nullptr, "CVodeCreate failed");
  Ok(CVodeInit(cv->mem, Rhs, 0.0, cv->y), "init");
  Ok(CVodeSetUserData(cv->mem, p), "user data");
  Ok(CVodeSetErrHandlerFn(cv->mem, OnError, p), "error handler");
  cv->atol = N_VNew_Serial(kBodyStateSize, cv->context);
  SetAbsoluteTolerances(c.model, sim.accuracy,
                        sim.stepper_values.Get(stepper_settings::velocity_time_scale),
                        cv->atol);
  Ok(CVodeSVtolerances(cv->mem, sim.accuracy, cv->atol), "tolerances");
  cv->matrix = SUNDenseMatrix(kBodyStateSize, kBodyStateSize, cv->context);
  cv->solver = SUNLinSol_Dense(cv->y, cv->matrix, cv->context);
  if (c.time_phases)
    cv->solver =
        TimedDense(cv->solver, c.Timing(&PhaseSeconds::linear_algebra), cv->context);
  Ok(CVodeSetLinearSolver(cv->mem, cv->solver, cv->matrix), "linear solver");
  if (!c.difference_quotient_jacobian) Ok(CVodeSetJacFn(cv->mem, Jacobian), "Jacobian");
  Ok(CVodeRootInit(cv->mem, 1, Root), "root");
  int falling = -1;
  Ok(CVodeSetRootDirection(cv->mem, &falling), "root direction");
  Ok(CVodeSetMaxNumSteps(cv->mem, 1000000), "step limit");
  Ok(CVodeSetMaxOrd(cv->mem, sim.stepper_values.Count(stepper_settings::max_order)),
     "maximum order");
  Ok(CVodeSetJacEvalFrequency(
         cv->mem, sim.stepper_values.Count(stepper_settings::jacobian_interval)),
     "Jacobian interval");
}

// CVODE's counters restart with it: the totals of the runs before.
struct RunTotals {
  TrialCounters done;
  long conv_fails = 0;

  // Adds the counters of the run now ending.
  void Harvest(void* mem) {
    long steps = 0, error_fails = 0, run_conv_fails = 0, rhs = 0, jac_rhs = 0,
         jacobians = 0;
    CVodeGetNumSteps(mem, &steps);
    CVodeGetNumJacEvals(mem, &jacobians);
    CVodeGetNumErrTestFails(mem, &error_fails);
    CVodeGetNumNonlinSolvConvFails(mem, &run_conv_fails);
    CVodeGetNumRhsEvals(mem, &rhs);
    CVodeGetNumLinRhsEvals(mem, &jac_rhs);
    done.steps_taken += steps;
    done.steps_attempted += steps + error_fails + run_conv_fails;
    done.error_test_failures += error_fails;
    done.realizations += rhs + jac_rhs;
    done.jacobian_evaluations += jacobians;
    conv_fails += run_conv_fails;
  }
};

// One trial stepped by CVODE from its first decision: step by step to each
// decision instant, every accepted step checked and sampled, restarted at
// each decision.
class CvodeRun {
 public:
  CvodeRun(TrialContext& c, const Decision& first, const contact::RigidMotion& start,
           double sample_interval)
      : c_(c),
        sim_(c.params().simulation),
        sample_interval_(sample_interval),
        deepening_limit_(kDeepeningLimit * c.model.contact.barrier_depth),
        checks_(c) {
    p_.c = &c;
    p_.held = first;
    SetUp(c, start, &p_, &cv_);
    c.integrated = true;
    kept_y_ = Of(cv_.y);
  }

  // Steps to completion, an ending or the time limit: the time reached.
  double Run(std::optional<TraceRow>* final_row, TrialCounters* counters) {
    const double limit = sim_.time_limit, interval = sim_.decision_interval;
    for (std::int64_t i = 1; !c_.ended && t_ < limit; ++i) {
      StepTo(std::min(static_cast<double>(i) * interval, limit));
      if (c_.ended || t_ >= limit) break;
      if (!Restart()) break;
    }
    totals_.Harvest(cv_.mem);
    counters->steps_taken = totals_.done.steps_taken;
    counters->steps_attempted = totals_.done.steps_attempted;
    counters->error_test_failures = totals_.done.error_test_failures;
    counters->realizations = totals_.done.realizations;
    counters->jacobian_evaluations = totals_.done.jacobian_evaluations;
    counters->convergence_failures = totals_.conv_fails;
    if (c_.completion_row)
      *final_row = c_.completion_row;
    else
      *final_row = FinalRow(c_, t_, MotionOf(Of(cv_.y)));
    return t_;
  }

 private:
  // CVODE's steps up to `stop`, a decision instant or the time limit.
  void StepTo(double stop) {
    Ok(CVodeSetStopTime(cv_.mem, stop), "stop time");
    checks_.Restarted();
    while (!c_.ended) {
      const int flag = CVode(cv_.mem, stop, cv_.y, &t_, CV_ONE_STEP);
      if (flag < 0) {
        c_.ended = Status::kNumericalFailure;
        c_.detail = fmt::format("CVODE stopped at t = {} s (flag {}): {}", t_, flag,
                                p_.last_error);
        c_.warnings.Note(WarningKind::kIntegratorFailure, t_, c_.detail);
        break;
      }
      if (!Step(flag, stop)) break;
    }
  }

  // The step CVODE took to t_, which returned `flag`: taken back, or checked,
  // sampled and kept. False when stepping to `stop` is over.
  bool Step(int flag, double stop) {
    // The accepted step: its checks, then the samples it covers.
    const BodyState y = Of(cv_.y);
    const contact::RigidMotion m = MotionOf(y);
    // The depth check needs the contact alone, not the operator's load.
    const double depth = IsFinite(m) ? c_.ContactAt(m).max_depth : 0.0;
    long conv_fails = 0;
    CVodeGetNumNonlinSolvConvFails(cv_.mem, &conv_fails);
    const long retries = totals_.conv_fails + conv_fails;
    double h = 0;
    CVodeGetLastStep(cv_.mem, &h);
    const BodyState slope = Slope();
    if (TakeBack(y, slope, depth, h)) {
      Retake(h, stop);
      return true;
    }
    if (step_capped_) {  // the retaken step passed: CVODE chooses again
      Ok(CVodeSetMaxStep(cv_.mem, 0.0), "step cap lifted");
      step_capped_ = false;
    }
    if (!checks_.Accepted(t_, m, depth, h, retries, [&] {
          return fmt::format("{} nonlinear convergence failures", retries);
        }))
      return false;
    // Samples in (before, t] on the same Hermite path, the one checked
    // above, rather than CVODE's own interpolant, a polynomial that also
    // carries the steps before this one.
    for (; sample_interval_ > 0; ++next_sample_) {
      const double ts = static_cast<double>(next_sample_) * sample_interval_;
      if (ts > t_ || ts >= sim_.time_limit) break;
      const contact::RigidMotion ms = PathAt(y, slope, ts);
      c_.samples.push_back(c_.SampleRow(ts, ms, c_.LoadsAt(ms, p_.held), p_.held.psi));
    }
    kept_y_ = y, kept_t_ = t_, kept_depth_ = depth, kept_slope_ = slope;
    if (flag == CV_ROOT_RETURN) {
      c_.ended = Status::kCompleted;
      c_.completion_time = t_;
      c_.completion_row = FinalRow(c_, t_, m);  // Table 1's instant d, at this state
      c_.detail = fmt::format("within {} m and {} deg of the target",
                              sim_.completion_distance, sim_.completion_angle_deg);
    }
    return !(flag == CV_TSTOP_RETURN || t_ >= stop);
  }

  // The slope at the step's end (CVODE's), and at its start once a step from
  // it has been taken since a (re)start: the step's cubic Hermite is the path
  // checked and sampled, when either is asked for; zero otherwise.
  BodyState Slope() {
    BodyState slope = BodyState::Zero();
    if (deepening_limit_ > 0 || sample_interval_ > 0) {
      CVodeGetDky(cv_.mem, t_, 1, cv_.dky);
      slope = Of(cv_.dky);
      if (!kept_slope_known_) {  // the first step since a (re)start
        CVodeGetDky(cv_.mem, kept_t_, 1, cv_.dky);
        kept_slope_ = Of(cv_.dky);
        kept_slope_known_ = true;
      }
    }
    return slope;
  }

  // The motion at ts on the step's path from the kept state to y.
  contact::RigidMotion PathAt(const BodyState& y, const BodyState& slope,
                              double ts) const {
    BodyState ys = Hermite(kept_t_, kept_y_, kept_slope_, t_, y, slope, ts);
    NormaliseQuaternion(&ys);
    return MotionOf(ys);
  }

  // A step that carries the contact deeper than kDeepeningLimit of the
  // barrier has jumped the contact's onset: CVODE's error test, in units of
  // position, cannot see micrometres, and the state it accepted lies in the
  // barrier's steep part, where the next steps' corrector fails
  // (docs/physics.md, Integrators). So has a step whose path passes through a
  // contact that neither end touches (the peg's rim grazing the bore's
  // chamfer within one step, 14 um deep between clear ends): its midpoint is
  // checked whenever the step moves the part's farthest point by more than
  // the limit, which no step in contact does. Either is taken back and
  // retaken with a quarter of the step; the depth is continuous in time, so
  // the retakes end. Not below the step floor.
  bool TakeBack(const BodyState& y, const BodyState& slope, double depth,
                double h) const {
    bool retake = false;
    if (deepening_limit_ > 0 && h > sim_.step_floor) {
      retake = depth - kept_depth_ > deepening_limit_;
      if (!retake && Travel(kept_y_, y, c_.model.bounding_radius) > deepening_limit_) {
        const contact::RigidMotion mid = PathAt(y, slope, kept_t_ + 0.5 * (t_ - kept_t_));
        retake =
            IsFinite(mid) &&
            c_.ContactAt(mid).max_depth - std::max(depth, kept_depth_) > deepening_limit_;
      }
    }
    return retake;
  }

  // Back to the kept state, CVODE restarted there with its step capped at a
  // quarter of h.
  void Retake(double h, double stop) {
    totals_.Harvest(cv_.mem);
    --totals_.done.steps_taken;  // attempted, not taken
    Of(cv_.y) = kept_y_;
    t_ = kept_t_;
    Ok(CVodeReInit(cv_.mem, t_, cv_.y), "retake");
    Ok(CVodeSetStopTime(cv_.mem, stop), "stop time");
    Ok(CVodeSetMaxStep(cv_.mem, 0.25 * h), "retake step");
    step_capped_ = true;
    checks_.Restarted();
  }

  // The decision at t_i: what the operator holds from now on; the
  // right-hand side changed, so CVODE restarts from this state. False when
  // the decision ended the trial.
  bool Restart() {
    BodyState y = Of(cv_.y);
    NormaliseQuaternion(&y);
    Of(cv_.y) = y;
    if (const std::optional<Decision> d = Decide(c_, t_, MotionOf(y))) p_.held = *d;
    if (c_.ended) return false;
    totals_.Harvest(cv_.mem);
    Ok(CVodeReInit(cv_.mem, t_, cv_.y), "restart");
    kept_y_ = y, kept_t_ = t_, kept_slope_known_ = false;
    return true;
  }

  TrialContext& c_;
  const scene::SimulationParams& sim_;
  const double sample_interval_;
  const double deepening_limit_;
  Problem p_;  // outlives cv_, whose callbacks see it
  Cvode cv_;
  RunTotals totals_;
  StepChecks checks_;
  std::int64_t next_sample_ = 1;
  double t_ = 0;
  // The last step kept, for a step taken back.
  BodyState kept_y_;
  double kept_t_ = 0, kept_depth_ = 0;
  bool step_capped_ = false;
  // Its slope, once a step from it has been taken since a (re)start.
  BodyState kept_slope_ = BodyState::Zero();
  bool kept_slope_known_ = false;
};

}  // namespace

double IntegrateWithCvode(TrialContext& c, double sample_interval,
                          std::optional<TraceRow>* final_row, TrialCounters* counters) {
  contact::RigidMotion start;
  start.pose = c.model.initial.Transform();
  const std::optional<Decision> first = Decide(c, 0.0, start);
  if (c.ended || !first) {  // ended at the first decision
    *final_row = FinalRow(c, 0.0, start);
    return 0.0;
  }
  CvodeRun run(c, *first, start, sample_interval);
  return run.Run(final_row, counters);
}

}  // namespace vahf::sim::internal
