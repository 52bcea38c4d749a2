// The stability experiment as trials (docs/experiments.md, "stability"): each
// case of the file, under each of its integrators, runs `seeds` trials of the
// part at its sequence position; a trial passes when its status is one of the
// classes the case expects, every number of its result is finite, and it kept
// within its step budget (simulation/max_steps).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "vahf/experiment/runner.h"
#include "vahf/experiment/stability_input.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/sim/trial_result.h"

namespace vahf::experiment {

struct StabilityTrial {
  std::size_t case_index = 0;        // into StabilityDesign::cases
  std::size_t integrator_index = 0;  // into the case's integrators (and scenes)
  int seed_index = 0;                // j: the trial's stream is the cycle j's
  sim::TrialResult result;
  // Why the trial fails its case (StabilityFailures); empty: it passes.
  std::vector<std::string> failures;
};

// Every case's trial models (one per integrator) are built before the first
// trial; then every trial, case-major, then integrator, then seed, on the
// runner's threads. Trial j of a case at sequence position p of an n-part
// scene draws from stream {seed, j n + p} (CycleKey), whatever the
// integrator: the integrators of a case meet the same operator. Same inputs:
// the same results but the measured times, whatever options.threads.
std::vector<StabilityTrial> RunStabilityTrials(const StabilityDesign& design,
                                               std::uint64_t seed,
                                               const RunnerOptions& options);

// Why `result` fails its case, one reason each (empty: it passes): its status
// is not one the case expects; a number of the result (end time, work, the
// deepest contact, the final row's pose, velocities, forces, factors, A and
// Psi_c) is not finite; it took more accepted steps than max_steps.
std::vector<std::string> StabilityFailures(const StabilityCase& c,
                                           const sim::TrialResult& result,
                                           std::int64_t max_steps);

// Whether `name` is a trial status name an expect list may hold.
bool IsOutcomeClass(const std::string& name);
// The status names, in Status order.
std::vector<std::string> OutcomeClasses();

}  // namespace vahf::experiment
