#include "vahf/sim/internal/stepping.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

#include "vahf/sim/internal/step_checks.h"

namespace vahf::sim::internal {
namespace {

// The checks of internal/step_checks.h at an accepted Simbody step, `s` realized
// through Acceleration (so the force element's loads are in its cache).
bool Accepted(SimbodyTrial& t, StepChecks& checks, const SimTK::Integrator& integ,
              const SimTK::State& s) {
  const std::int64_t retries =
      static_cast<std::int64_t>(integ.getNumConvergenceTestFailures()) +
      integ.getNumRealizationFailures() + integ.getNumProjectionFailures();
  return checks.Accepted(s.getTime(), t.MotionOf(s), t.LoadsOf(s).contact.max_depth,
                         integ.getPreviousStepSizeTaken(), retries, [&] {
                           return fmt::format(
                               "{} convergence, {} realization, {} projection failures",
                               integ.getNumConvergenceTestFailures(),
                               integ.getNumRealizationFailures(),
                               integ.getNumProjectionFailures());
                         });
}

// A dense trace row at a sample state.
TraceRow SampleRow(SimbodyTrial& t, const SimTK::State& s) {
  t.system().realize(s, SimTK::Stage::Dynamics);
  return t.context().SampleRow(s.getTime(), t.MotionOf(s), t.LoadsOf(s),
                               t.HeldDecision(s).psi);
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
        x.updQ() =
            h00 * q0_ + (h10 * h) * qdot0_ + h01 * now.getQ() + (h11 * h) * now.getQDot();
        x.updU() =
            h00 * u0_ + (h10 * h) * udot0_ + h01 * now.getU() + (h11 * h) * now.getUDot();
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
// returning at every accepted step (StepChecks, Sampler). Returns the time
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
  StepChecks checks(c);
  Sampler sampler(t, sample_interval);
  sampler.Advanced(integ.getState(), limit);
  SimTK::Array_<SimTK::EventId> scheduled;
  double last_event_time = -SimTK::Infinity;
  const auto handle = [&](SimTK::Event::Cause cause,
                          const SimTK::Array_<SimTK::EventId>& ids) {
    SimTK::HandleEventsResults results;
    system.handleEvents(integ.updAdvancedState(), cause, ids, handle_options, results);
    integ.reinitialize(
        results.getLowestModifiedStage(),
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
      if (!Accepted(t, checks, integ, integ.getState())) break;
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
      default:     // TimeHasAdvanced, ReachedReportTime, StartOfContinuousInterval,
        continue;  // ReachedStepLimit: step on
    }
    checks.Restarted();
    // An event may have changed what the forces depend on (a decision):
    // interpolate the next step from the state after it.
    system.realize(integ.getState(), SimTK::Stage::Acceleration);
    sampler.Advanced(integ.getState(), limit);
  }
  return integ.getTime();
}

}  // namespace vahf::sim::internal
