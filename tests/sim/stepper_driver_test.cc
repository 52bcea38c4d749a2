// The shared driver of the steppers of the trial model's own right-hand side
// (sim/internal/stepper_driver.h) with a test-only core: classical RK4 at a
// fixed step on RightHandSide::Derivative, which finds no roots, so the
// driver locates completion on each step's path. The block of
// support/free_fall.h falls onto a target below it: the trial completes
// where the completion witness crosses zero (to the driver's tolerance),
// samples come at the asked interval on the analytic path, the counters are
// the core's, and the trial agrees with CVODE's. A new stepper needs only
// its core: everything else here is the driver's.
#include "vahf/sim/internal/stepper_driver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

#include "support/free_fall.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/stepper_core.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim {
namespace {

constexpr double kStep = 1e-3;  // s, the RK4 core's step

// Classical fourth-order Runge-Kutta at a fixed step (shortened to land on
// each stop), its quaternion normalised after each step.
class Rk4Core : public StepperCore {
 public:
  Rk4Core(RightHandSide& rhs, const BodyState& start) : rhs_(rhs) { Reset(0.0, start); }

  void Reset(double t, const BodyState& y) override {
    t_ = t0_ = t, y_ = y;
    slope_known_ = false;
  }
  void Retake(double t, const BodyState& y, double max_step) override {
    Reset(t, y);
    cap_ = max_step;
  }
  void Kept() override { cap_ = 0; }

  StepOutcome StepTo(double stop) override {
    StepOutcome o;
    const double h0 = cap_ > 0 ? std::min(kStep, cap_) : kStep;
    o.h = stop - t_ <= h0 * (1 + 1e-9) ? stop - t_ : h0;
    BodyState k1, k2, k3, k4;
    if (!(Eval(y_, &k1) && Eval(y_ + 0.5 * o.h * k1, &k2) &&
          Eval(y_ + 0.5 * o.h * k2, &k3) && Eval(y_ + o.h * k3, &k4))) {
      o.kind = StepOutcome::kFailed;
      o.detail = "RK4: the state is not finite";
      o.t = t_;
      return o;
    }
    t0_ = t_, start_slope_ = k1;
    y_ += o.h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    NormaliseQuaternion(&y_);
    t_ = o.h == stop - t0_ ? stop : t0_ + o.h;
    slope_known_ = false;
    ++steps_;
    o.t = t_;
    o.kind = t_ >= stop ? StepOutcome::kReachedStop : StepOutcome::kStepped;
    return o;
  }

  BodyState State() const override { return y_; }

  // k1 at the step's start; f(y) at its end, evaluated once.
  BodyState Slope(double t) override {
    if (t == t0_ && t != t_) return start_slope_;
    if (!slope_known_) slope_known_ = Eval(y_, &end_slope_);
    return end_slope_;
  }

  void SetCounters(TrialCounters* counters) override {
    counters->steps_taken = counters->steps_attempted = steps_;
    counters->realizations = evaluations_;
  }

 private:
  bool Eval(const BodyState& y, BodyState* dydt) {
    ++evaluations_;
    return rhs_.Derivative(y, dydt);
  }

  RightHandSide& rhs_;
  double t_ = 0, t0_ = 0, cap_ = 0;
  BodyState y_, start_slope_ = BodyState::Zero(), end_slope_ = BodyState::Zero();
  bool slope_known_ = false;
  std::int64_t steps_ = 0, evaluations_ = 0;
};

std::unique_ptr<StepperCore> MakeRk4(RightHandSide& rhs, const BodyState& start) {
  return std::make_unique<Rk4Core>(rhs, start);
}

constexpr double kG = 9.80665;    // the scene's gravity, m/s^2
constexpr double kTargetZ = 0.5;  // m, below the block's start at 1 m
// simulation/completion_distance, m: wide enough that the block is within
// it for 33 ms, many steps (at the default 1 mm, 0.6 ms: between two step
// ends, and neither this driver nor CVODE's root finder sees a witness that
// dips and returns within one step).
constexpr double kThreshold = 0.05;
constexpr double kSampleInterval = 0.01;  // s

// The block falls from rest at 1 m onto a target at kTargetZ: completion
// when it is kThreshold above it, at sqrt(2 (1 - kTargetZ - kThreshold) / g).
scene::Scene FallOntoTarget(const std::string& integrator) {
  nlohmann::json doc = testing::FreeFallScene({{"time_limit", 1.0},
                                               {"decision_interval", 0.05},
                                               {"integrator", integrator},
                                               {"accuracy", 1e-10},
                                               {"completion_distance", kThreshold}});
  doc["parts"][0]["target"]["position"] = {0.0, 0.0, kTargetZ};
  return scene::ParseScene(doc, "fall.json");
}

const double kCompletion = std::sqrt(2 * (1.0 - kTargetZ - kThreshold) / kG);

// A trial of `model` (seed 1) as DriveTrial leaves it.
struct Driven {
  explicit Driven(const TrialModel& model) : c(model, {1, 0}) {}
  internal::TrialContext c;
  double end = 0;
  std::optional<TraceRow> final_row;
  TrialCounters counters;
};

void Drive(Driven* d, CoreFactory make) {
  d->end = internal::DriveTrial(d->c, make, kSampleInterval, &d->final_row, &d->counters);
}

TEST(StepperDriver, LocatesCompletionOnTheStepsPathForACoreWithoutRoots) {
  const auto model = BuildTrialModel(FallOntoTarget("CVODE"), 0);
  Driven d(*model);
  Drive(&d, MakeRk4);
  ASSERT_EQ(d.c.ended, Status::kCompleted) << d.c.detail;
  // RK4 and the cubic Hermite path are exact for the fall's parabola, so the
  // completion time is the witness's zero to the bisection's tolerance.
  EXPECT_NEAR(d.c.completion_time, kCompletion, 2 * internal::kCompletionTolerance);
  EXPECT_EQ(d.end, d.c.completion_time);
  ASSERT_TRUE(d.final_row);
  EXPECT_EQ(d.final_row->time, d.c.completion_time);
  EXPECT_NEAR(d.final_row->position.z(), kTargetZ + kThreshold, 1e-9);
  // Within the threshold at completion, and not yet a tolerance before.
  const auto motion_at = [&](double t) {
    contact::RigidMotion m;
    m.pose.setIdentity();
    m.pose.translation() = Eigen::Vector3d(0, 0, 1.0 - 0.5 * kG * t * t);
    return m;
  };
  EXPECT_LE(model->CompletionWitness(motion_at(d.c.completion_time)), 1e-8);
  EXPECT_GT(model->CompletionWitness(
                motion_at(d.c.completion_time - 3 * internal::kCompletionTolerance)),
            0);
}

TEST(StepperDriver, SamplesAtTheAskedIntervalUpToCompletion) {
  const auto model = BuildTrialModel(FallOntoTarget("CVODE"), 0);
  Driven d(*model);
  Drive(&d, MakeRk4);
  const auto expected = static_cast<std::size_t>(kCompletion / kSampleInterval);
  ASSERT_EQ(d.c.samples.size(), expected);
  for (std::size_t k = 0; k < expected; ++k) {
    const TraceRow& row = d.c.samples[k];
    EXPECT_EQ(row.time, static_cast<double>(k + 1) * kSampleInterval);
    EXPECT_NEAR(row.position.z(), 1.0 - 0.5 * kG * row.time * row.time, 1e-12) << k;
    EXPECT_NEAR(row.velocity.z(), -kG * row.time, 1e-12) << k;
  }
}

// The core's counters reach the trial: one step a millisecond (each decision
// interval of 50 ms is 50 of them) with four right-hand sides each, and one
// more for the end slope of each step the driver's path uses.
TEST(StepperDriver, FillsTheCoresCounters) {
  const auto model = BuildTrialModel(FallOntoTarget("CVODE"), 0);
  Driven d(*model);
  Drive(&d, MakeRk4);
  const auto steps = static_cast<std::int64_t>(std::ceil(kCompletion / kStep));
  EXPECT_EQ(d.counters.steps_taken, steps);
  EXPECT_EQ(d.counters.steps_attempted, steps);
  EXPECT_EQ(d.counters.realizations, 5 * steps);
  EXPECT_TRUE(d.c.integrated);
}

// The same trial under CVODE (through RunTrial and the registry) completes
// at the same time within 1e-6 s: CVODE's root finder locates the crossing
// of its own interpolant, held to `accuracy` 1e-10.
TEST(StepperDriver, AgreesWithCvodeOnTheSameTrial) {
  const auto model = BuildTrialModel(FallOntoTarget("CVODE"), 0);
  Driven d(*model);
  Drive(&d, MakeRk4);
  const TrialResult cvode = RunTrial(*model, {1, 0}, {0, 0.0, true, kSampleInterval});
  ASSERT_EQ(cvode.status, Status::kCompleted) << cvode.detail;
  EXPECT_NEAR(d.c.completion_time, cvode.completion_time, 1e-6);
  ASSERT_EQ(d.c.samples.size(), cvode.samples.size());
  for (std::size_t k = 0; k < cvode.samples.size(); ++k)
    EXPECT_NEAR(d.c.samples[k].position.z(), cvode.samples[k].position.z(), 1e-8) << k;
}

}  // namespace
}  // namespace vahf::sim
