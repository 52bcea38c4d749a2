#include "vahf/sim/stepping.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

namespace vahf::sim::internal {
namespace {

// The checks made at every accepted step (docs/design.md decision 12): the
// state is finite, the contact depth is within the bound, the step is above
// the floor, and the integrator's retries since the last step are counted.
// Returns false when the state is unusable (the trial ends).
class StepWatch {
 public:
  explicit StepWatch(SimbodyTrial& t) : t_(t), c_(t.context()) {}

  // `s` is realized through Acceleration.
  bool Accepted(const SimTK::Integrator& integ, const SimTK::State& s) {
    const double t = s.getTime();
    const contact::RigidMotion m = t_.MotionOf(s);
    if (std::optional<Ending> bad = CheckState(
            m, c_.model.part->mass_properties.bounding_radius, c_.params().simulation,
            "a step after decision", c_.last_decision, t)) {
      if (!IsFinite(m)) c_.warnings.Note(WarningKind::kNonFiniteState, t, bad->detail);
      c_.End(std::move(*bad));
      return false;
    }
    Depth(t_.LoadsOf(s).contact.max_depth, t);
    const double h = integ.getPreviousStepSizeTaken();
    const double floor = c_.params().simulation.step_floor;
    // The first steps after a start or an event are the integrator probing
    // its step size (CPodes begins near 1e-11 s), not a sign of trouble.
    if (++steps_since_restart_ > kProbingSteps && h > 0 && h < floor)
      c_.warnings.Count(WarningKind::kStepSizeFloor, t, [&] {
        return fmt::format("step {:.3g} s < floor {:.3g} s", h, floor);
      });
    const std::int64_t retries = static_cast<std::int64_t>(integ.getNumConvergenceTestFailures()) +
                                 integ.getNumRealizationFailures() +
                                 integ.getNumProjectionFailures();
    if (retries > retries_)
      c_.warnings.Count(
          WarningKind::kIntegratorRetry, t,
          [&] {
            return fmt::format("{} convergence, {} realization, {} projection failures",
                               integ.getNumConvergenceTestFailures(),
                               integ.getNumRealizationFailures(),
                               integ.getNumProjectionFailures());
          },
          retries - retries_);
    retries_ = retries;
    return true;
  }

  // The integrator restarted (initialization or an event handled).
  void Restarted() { steps_since_restart_ = 0; }

 private:
  // The deepest contact so far, and a warning past the bound.
  void Depth(double depth, double t) {
    c_.max_penetration = std::max(c_.max_penetration, depth);
    const TrialModel& model = c_.model;
    if (model.penetration_bound > 0 && depth > model.penetration_bound)
      c_.warnings.Count(WarningKind::kPenetrationBound, t, [&] {
        return fmt::format("depth {:.3g} um > bound {:.3g} um ({} of the {:.3g} um radial "
                           "clearance)",
                           depth * 1e6, model.penetration_bound * 1e6,
                           c_.params().contact.penetration_fraction, model.clearance * 1e6);
      });
  }

  SimbodyTrial& t_;
  TrialContext& c_;
  std::int64_t retries_ = 0;
  static constexpr int kProbingSteps = 3;
  int steps_since_restart_ = 0;
};

// A dense trace row at a sample state.
TraceRow SampleRow(SimbodyTrial& t, const SimTK::State& s) {
  t.system().realize(s, SimTK::Stage::Dynamics);
  const Loads& loads = t.LoadsOf(s);
  TraceRow row = TrialContext::PoseRow(s.getTime(), t.MotionOf(s));
  row.assembly_force = loads.assembly_force;
  row.contact_force = loads.contact.normal_force;
  row.friction_force = loads.contact.friction_force;
  row.penetration = loads.contact.max_depth;
  row.work = t.context().work;
  row.psi = t.HeldDecision(s).psi;
  return row;
}

// Dense samples between accepted steps, by cubic Hermite interpolation of q
// (with qdot) and u (with udot) between the two step ends, the quaternion
// renormalised: third order, and the integrator never sees a sample time, so
// the trajectory is the same bits with and without samples whatever the
// integrator (asking the integrator for report times would not be: CPodes
// stops its steps at them).
class Sampler {
 public:
  Sampler(SimbodyTrial& t, double interval) : t_(t), interval_(interval) {}

  // The integrator advanced to state `now` (realized to Acceleration): emit
  // every sample time in (previous, now], then remember `now`.
  void Advanced(const SimTK::State& now, double limit) {
    if (interval_ <= 0) return;
    if (have_previous_ && now.getTime() > t0_) {
      const double t1 = now.getTime(), h = t1 - t0_;
      for (;;) {
        const double t = static_cast<double>(next_) * interval_;
        if (t > t1 || t >= limit) break;
        const double s = (t - t0_) / h;
        // Hermite basis on [0, 1].
        const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
        const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
        SimTK::State x = now;
        x.setTime(t);
        x.updQ() = h00 * q0_ + (h10 * h) * qdot0_ + h01 * now.getQ() + (h11 * h) * now.getQDot();
        x.updU() = h00 * u0_ + (h10 * h) * udot0_ + h01 * now.getU() + (h11 * h) * now.getUDot();
        t_.system().realize(x, SimTK::Stage::Position);
        t_.system().project(x, 1e-10);  // the quaternion back to unit length
        t_.context().samples.push_back(SampleRow(t_, x));
        ++next_;
      }
    }
    have_previous_ = true;
    t0_ = now.getTime();
    q0_ = now.getQ();
    qdot0_ = now.getQDot();
    u0_ = now.getU();
    udot0_ = now.getUDot();
  }

 private:
  SimbodyTrial& t_;
  double interval_;
  std::int64_t next_ = 1;
  bool have_previous_ = false;
  double t0_ = 0;
  SimTK::Vector q0_, qdot0_, u0_, udot0_;
};

}  // namespace

// Steps from the initial state to completion, an ending or the time limit,
// returning at every accepted step (StepWatch, Sampler). Returns the time
// reached.
//
// The loop is SimTK::TimeStepper::stepTo's (Simbody 3.7, TimeStepper.cpp),
// returning at every internal step; time-advanced events are not dispatched
// (the system has none).
double Integrate(SimbodyTrial& t, SimTK::Integrator& integ, double sample_interval) {
  using SimTK::Integrator;
  TrialContext& c = t.context();
  const SimTK::MultibodySystem& system = t.system();
  const double limit = c.params().simulation.time_limit;
  integ.setReturnEveryInternalStep(true);
  integ.initialize(t.initial_state());
  c.integrated = true;
  SimTK::HandleEventsOptions handle_options(integ.getConstraintToleranceInUse());
  if (integ.isInfinityNormInUse())
    handle_options.setOption(SimTK::HandleEventsOptions::UseInfinityNorm);
  StepWatch watch(t);
  Sampler sampler(t, sample_interval);
  sampler.Advanced(integ.getState(), limit);
  SimTK::Array_<SimTK::EventId> scheduled;
  double last_event_time = -SimTK::Infinity;
  const auto handle = [&](SimTK::Event::Cause cause, const SimTK::Array_<SimTK::EventId>& ids) {
    SimTK::HandleEventsResults results;
    system.handleEvents(integ.updAdvancedState(), cause, ids, handle_options, results);
    integ.reinitialize(results.getLowestModifiedStage(),
                       results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate);
  };
  while (!integ.isSimulationOver() && !c.ended) {
    const double now = integ.getTime();
    if (now >= limit) break;
    system.realize(integ.getState(), SimTK::Stage::Time);
    system.realize(integ.getAdvancedState(), SimTK::Stage::Time);
    double next_event = SimTK::Infinity;
    system.calcTimeOfNextScheduledEvent(integ.getState(), next_event, scheduled,
                                        last_event_time != now);
    const Integrator::SuccessfulStepStatus status =
        integ.stepTo(limit, std::min(next_event, limit));
    if (integ.getTime() > now) {  // the trajectory advanced to integ.getState()
      system.realize(integ.getState(), SimTK::Stage::Acceleration);
      if (!watch.Accepted(integ, integ.getState())) break;
      sampler.Advanced(integ.getState(), limit);
    }
    switch (status) {
      case Integrator::ReachedScheduledEvent:
        handle(SimTK::Event::Cause::Scheduled, scheduled);
        last_event_time = integ.getTime();
        break;
      case Integrator::ReachedEventTrigger:
        handle(SimTK::Event::Cause::Triggered, integ.getTriggeredEvents());
        break;
      case Integrator::EndOfSimulation:
        handle(SimTK::Event::Cause::Termination, {});
        break;
      default:  // TimeHasAdvanced, ReachedReportTime, StartOfContinuousInterval,
        continue;  // ReachedStepLimit: step on
    }
    watch.Restarted();
    // An event may have changed what the forces depend on (a decision):
    // interpolate the next step from the state after it.
    system.realize(integ.getState(), SimTK::Stage::Acceleration);
    sampler.Advanced(integ.getState(), limit);
  }
  return integ.getTime();
}

}  // namespace vahf::sim::internal
