// One assembly cycle: the scene's sequence assembled part after part (paper
// Fig. 9: piston rod, guide sleeve, seal ring), each part a trial that starts
// with the work A the operator has done so far (Eq. 4) and ends where the next
// begins. A part that fails ends the cycle: the later parts are not attempted.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "vahf/scene/scene.h"
#include "vahf/sim/trial_model.h"
#include "vahf/sim/trial_result.h"

namespace vahf::experiment {

struct PartRun {
  sim::TrialResult trial;
  double start_time = 0;  // s from the cycle's start
  double start_work = 0;  // A when it began, J
};

struct CycleResult {
  std::vector<PartRun> parts;  // in sequence order, up to the first failure
  bool completed = false;      // every part of the sequence completed
  double time = 0;             // s: to the last completion, or to the failure
  double work = 0;             // A at the end, J (includes the initial work)
  // A part's trial ended as a failure of the computation (numerical_failure
  // or step_budget, sim::IsComputationFailure): the cycle says nothing about
  // the assembly and is left out of success rates (reported apart, counted
  // as numerical failures).
  bool numerical_failure = false;
  Warnings warnings;  // the sum of its part trials' records
};

// The stream of sequence position p in cycle c is keyed {seed, c * n + p}, n
// the sequence length: cycles never share a stream, and two conditions run
// with the same seed and cycle index share theirs (common random numbers).
rng::StreamKey CycleKey(std::uint64_t seed, std::uint64_t cycle, std::size_t n,
                        std::size_t position);

// The trial models of a scene's sequence (sim::BuildSequenceModels): built
// once per scene of an experiment and shared by all its cycles.
using SequenceModels = std::vector<std::shared_ptr<const sim::TrialModel>>;

// `repetition` (from 1): the operator's repetition of the task, which every
// part trial of the cycle is (sim::TrialOptions::repetition).
// `sample_interval` > 0: each part trial's trace also samples every that
// many s (sim::TrialOptions::sample_interval; the trajectory is unchanged).
CycleResult RunCycle(const SequenceModels& models, std::uint64_t seed,
                     std::uint64_t cycle, double initial_work, bool record_trace,
                     int repetition = 1, double sample_interval = 0);
// Builds the scene's models, then runs the cycle.
CycleResult RunCycle(const scene::Scene& scene, std::uint64_t seed, std::uint64_t cycle,
                     double initial_work, bool record_trace, int repetition = 1);

}  // namespace vahf::experiment
