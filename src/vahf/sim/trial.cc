#include "vahf/sim/trial.h"

#include <Simbody.h>
#include <fmt/format.h>

#include <chrono>
#include <optional>

#include "vahf/core/thread_cpu.h"
#include "vahf/core/warnings.h"
#include "vahf/human/learning.h"
#include "vahf/sim/internal/simbody_trial.h"
#include "vahf/sim/internal/stepper_driver.h"
#include "vahf/sim/internal/stepping.h"
#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/stepper_registry.h"

namespace vahf::sim {
namespace {

using namespace internal;  // the trial context, its Simbody model, the stepping loop

// The Simbody driver: steps the trial through Simbody with the stepper's
// integrator from its first decision to its end: the time reached and the row
// at the end, the trial ending in numerical failure if the integrator stops
// early or throws.
double IntegrateWithSimbody(IntegratorFactory make_integrator, TrialContext& c,
                            double sample_interval, std::optional<TraceRow>* final_row,
                            TrialCounters* counters) {
  SimbodyTrial t(c);  // makes the decision at t = 0
  if (c.ended) {      // ended at the first decision
    SimTK::State initial = t.initial_state();
    *final_row = t.FinalRow(initial);
    return 0.0;
  }
  const auto integ = make_integrator(t.system(), c.params().simulation);
  double end_time = 0;
  try {
    end_time = Integrate(t, *integ, sample_interval);
    if (c.completion_row) {
      *final_row = c.completion_row;
    } else {
      SimTK::State end_state = integ->getState();
      *final_row = t.FinalRow(end_state);
    }
    if (!c.ended && integ->isSimulationOver() &&
        integ->getTerminationReason() != SimTK::Integrator::ReachedFinalTime) {
      c.ended = Status::kNumericalFailure;
      c.detail = fmt::format(
          "integrator stopped at t = {} s: {}", end_time,
          SimTK::Integrator::getTerminationReasonString(integ->getTerminationReason()));
      c.warnings.Note(WarningKind::kIntegratorFailure, end_time, c.detail);
    }
  } catch (const std::exception& e) {
    end_time = integ->getTime();
    c.ended = Status::kNumericalFailure;
    c.detail = fmt::format("at t = {} s: {}", end_time, e.what());
    c.warnings.Note(WarningKind::kIntegratorFailure, end_time, c.detail);
  }
  if (c.integrated) {  // an integrator never initialized has no counts to read
    counters->steps_taken = integ->getNumStepsTaken();
    counters->steps_attempted = integ->getNumStepsAttempted();
    counters->error_test_failures = integ->getNumErrorTestFailures();
    counters->realizations = integ->getNumRealizations();
  }
  return end_time;
}

// Runs the stepper: a Simbody one's integrator under the Simbody driver, or
// a core of the trial model's own right-hand side under the shared driver.
double RunStepper(const StepperEntry& stepper, TrialContext& c, double sample_interval,
                  std::optional<TraceRow>* final_row, TrialCounters* counters) {
  if (stepper.needs == scene::StepperNeeds::kSimbodySystem)
    return IntegrateWithSimbody(stepper.make_integrator, c, sample_interval, final_row,
                                counters);
  return DriveTrial(c, stepper.make_core, sample_interval, final_row, counters);
}

}  // namespace

TrialResult RunTrial(const TrialModel& model, rng::StreamKey key,
                     const TrialOptions& options) {
  const auto& params = model.params;
  TrialContext c(model, key);
  c.work = options.initial_work;
  c.practice_gain = human::PracticeGain(params.learning, options.repetition);
  c.record_trace = options.record_trace;
  c.difference_quotient_jacobian = options.difference_quotient_jacobian;
  c.depth_pass_every_step = options.depth_pass_every_step;
  c.time_phases = options.time_phases;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = ThreadCpuSeconds();
  TrialResult result;
  TrialCounters counters;
  std::optional<TraceRow> final_row;
  const double end_time = RunStepper(FindStepper(params.simulation.integrator), c,
                                     options.sample_interval, &final_row, &counters);
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = ThreadCpuSeconds() - cpu_start;
  result.phases = c.phases;
  result.status = c.ended.value_or(Status::kTimeout);
  if (!c.ended) c.detail = fmt::format("time limit {} s", params.simulation.time_limit);
  result.detail = c.detail;
  result.end_time = result.status == Status::kCompleted ? c.completion_time : end_time;
  result.completion_time = c.completion_time;
  result.first_contact_time = c.first_contact_time;
  result.part = model.part_name;
  result.integrator = params.simulation.integrator;
  result.accuracy = params.simulation.accuracy;
  result.key = key;
  counters.decisions = c.last_decision + 1;
  counters.rays_cast = c.rays_cast;
  counters.shell_points = model.contact.shell_points;
  if (model.contact.model) {
    const contact::ContactCounters& cc = c.contact_counters;
    counters.contact_evaluations = static_cast<std::int64_t>(cc.evaluations);
    counters.contact_point_queries = static_cast<std::int64_t>(cc.point_queries);
    counters.contact_tests = static_cast<std::int64_t>(cc.Tests());
    counters.broad_phase_skips = static_cast<std::int64_t>(cc.pairs_skipped);
    counters.clusters_skipped = static_cast<std::int64_t>(cc.clusters_skipped);
  }
  result.counters = counters;
  c.Rested(c.rests.Close(params.simulation));  // a rest the ending cut short
  result.rests = c.rests.summary();
  result.warnings = c.warnings;
  result.max_penetration = c.max_penetration;
  result.penetration_bound = model.penetration_bound;
  result.clearance = model.clearance;
  result.stiffness = model.contact.stiffness;
  result.line_stiffness = model.contact.line_stiffness;
  result.samples = std::move(c.samples);
  if (!final_row) {  // the integrator threw: the last decision is the last known row
    final_row = c.trace.empty() ? TraceRow{} : c.trace.back();
    final_row->work = c.work;
  }
  result.final_row = *final_row;
  result.work = final_row->work;
  result.trace = std::move(c.trace);
  return result;
}

TrialResult RunTrial(const scene::Scene& scene, rng::StreamKey key,
                     const TrialOptions& options) {
  return RunTrial(*BuildTrialModel(scene, options.sequence_position), key, options);
}

}  // namespace vahf::sim
