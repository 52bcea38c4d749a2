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
#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/rigid_body.h"
#include "vahf/sim/rigid_body_jacobian.h"

namespace vahf::sim::internal {
namespace {

namespace stepper_settings = scene::stepper_settings;

// What CVODE's callbacks see.
struct Problem {
  RightHandSide* rhs = nullptr;  // under the held decision
  std::string last_error;        // CVODE's last message, for the failure's detail
};

Eigen::Map<BodyState> Of(N_Vector v) {
  return Eigen::Map<BodyState>(N_VGetArrayPointer(v));
}

int Rhs(realtype, N_Vector y, N_Vector ydot, void* data) {
  Problem& p = *static_cast<Problem*>(data);
  BodyState dydt;
  // Not finite: recoverable, CVODE retries with a smaller step.
  if (!p.rhs->Derivative(Of(y), &dydt)) return 1;
  Of(ydot) = dydt;
  return 0;
}

// The analytic Jacobian (rigid_body_jacobian.h) from one contact pass with
// its derivative, instead of CVODE's 13 difference quotients.
int Jacobian(realtype, N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector,
             N_Vector) {
  Problem& p = *static_cast<Problem*>(data);
  TrialContext& c = p.rhs->context();
  const PhaseTimer timer(c.Timing(&PhaseSeconds::jacobian));
  const BodyState state = Of(y);
  const contact::RigidMotion m = MotionOf(state);
  if (!IsFinite(m)) return 1;  // recoverable, as in Rhs
  LoadJacobian dloads;
  const Loads loads = c.model.LoadsAt(m, p.rhs->held(), &c.contact_counters, &dloads);
  c.Evaluated(m, loads.contact.max_depth);
  const BodyJacobian jacobian =
      DerivativeJacobian(c.model, state, loads, dloads, c.model.gravity);
  for (int j = 0; j < kBodyStateSize; ++j)
    for (int i = 0; i < kBodyStateSize; ++i) SM_ELEMENT_D(J, i, j) = jacobian(i, j);
  return 0;
}

// The completion witness: falls through zero when the part is within both
// thresholds.
int Root(realtype, N_Vector y, realtype* g, void* data) {
  const Problem& p = *static_cast<const Problem*>(data);
  g[0] = p.rhs->model().CompletionWitness(MotionOf(Of(y)));
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

void Ok(int flag, const char* what) {
  VAHF_CHECK(flag >= 0, std::string("CVODE set-up failed: ") + what);
}

// CVODE set up for the trial of rhs from the part's state `start` at t = 0:
// BDF with Newton iteration, the dense linear solver (timed when the trial
// asks), the analytic Jacobian unless it asks for difference quotients, root
// finding on the completion witness, and the scene's order and Jacobian
// interval.
void SetUp(RightHandSide& rhs, const BodyState& start, Problem* p, Cvode* cv) {
  TrialContext& c = rhs.context();
  const auto& sim = rhs.settings();
  Ok(SUNContext_Create(nullptr, &cv->context), "context");
  cv->y = N_VNew_Serial(kBodyStateSize, cv->context);
  cv->dky = N_VNew_Serial(kBodyStateSize, cv->context);
  Of(cv->y) = start;
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

// CVODE as a core of the shared driver (internal/stepper_driver.h): one
// step of its own at a time (CV_ONE_STEP), restarted at each decision and
// after a take-back, its root finding the trial's completion.
class CvodeCore : public StepperCore {
 public:
  CvodeCore(RightHandSide& rhs, const BodyState& start) {
    p_.rhs = &rhs;
    SetUp(rhs, start, &p_, &cv_);
  }

  // The decision changed the right-hand side: CVODE restarts at (t, y).
  void Reset(double t, const BodyState& y) override {
    Of(cv_.y) = y;
    t_ = t;
    totals_.Harvest(cv_.mem);
    Ok(CVodeReInit(cv_.mem, t, cv_.y), "restart");
  }

  // Back to (t, y), CVODE restarted there with its step capped.
  void Retake(double t, const BodyState& y, double max_step) override {
    totals_.Harvest(cv_.mem);
    --totals_.done.steps_taken;  // attempted, not taken
    Of(cv_.y) = y;
    t_ = t;
    Ok(CVodeReInit(cv_.mem, t, cv_.y), "retake");
    Ok(CVodeSetStopTime(cv_.mem, stop_), "stop time");
    Ok(CVodeSetMaxStep(cv_.mem, max_step), "retake step");
    step_capped_ = true;
  }

  void Kept() override {
    if (step_capped_) {  // the retaken step passed: CVODE chooses again
      Ok(CVodeSetMaxStep(cv_.mem, 0.0), "step cap lifted");
      step_capped_ = false;
    }
  }

  StepOutcome StepTo(double stop) override {
    if (stop != stop_) {
      Ok(CVodeSetStopTime(cv_.mem, stop), "stop time");
      stop_ = stop;
    }
    const int flag = CVode(cv_.mem, stop, cv_.y, &t_, CV_ONE_STEP);
    StepOutcome o;
    o.t = t_;
    if (flag < 0) {
      o.kind = StepOutcome::kFailed;
      o.detail = fmt::format("CVODE stopped at t = {} s (flag {}): {}", o.t, flag,
                             p_.last_error);
      return o;
    }
    long conv_fails = 0;
    CVodeGetNumNonlinSolvConvFails(cv_.mem, &conv_fails);
    o.retries = totals_.conv_fails + conv_fails;
    CVodeGetLastStep(cv_.mem, &o.h);
    if (flag == CV_ROOT_RETURN)
      o.kind = StepOutcome::kCompleted;
    else if (flag == CV_TSTOP_RETURN || o.t >= stop)
      o.kind = StepOutcome::kReachedStop;
    return o;
  }

  BodyState State() const override { return Of(cv_.y); }

  // CVODE's own interpolant's slope at t.
  BodyState Slope(double t) override {
    CVodeGetDky(cv_.mem, t, 1, cv_.dky);
    return Of(cv_.dky);
  }

  bool FindsRoots() const override { return true; }

  std::string RetryDetail(std::int64_t retries) const override {
    return fmt::format("{} nonlinear convergence failures", retries);
  }

  void SetCounters(TrialCounters* counters) override {
    totals_.Harvest(cv_.mem);
    counters->steps_taken = totals_.done.steps_taken;
    counters->steps_attempted = totals_.done.steps_attempted;
    counters->error_test_failures = totals_.done.error_test_failures;
    counters->realizations = totals_.done.realizations;
    counters->jacobian_evaluations = totals_.done.jacobian_evaluations;
    counters->convergence_failures = totals_.conv_fails;
  }

 private:
  Problem p_;  // outlives cv_, whose callbacks see it
  Cvode cv_;
  RunTotals totals_;
  double t_ = 0;      // the time CVODE reached
  double stop_ = -1;  // the stop time CVODE was given
  bool step_capped_ = false;
};

}  // namespace

std::unique_ptr<StepperCore> MakeCvodeCore(RightHandSide& rhs, const BodyState& start) {
  return std::make_unique<CvodeCore>(rhs, start);
}

}  // namespace vahf::sim::internal
