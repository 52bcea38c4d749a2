#include "vahf/experiment/cycle.h"

#include "vahf/sim/trial.h"

namespace vahf::experiment {

rng::StreamKey CycleKey(std::uint64_t seed, std::uint64_t cycle, std::size_t n,
                        std::size_t position) {
  return {seed, cycle * n + position};
}

CycleResult RunCycle(const SequenceModels& models, std::uint64_t seed,
                     std::uint64_t cycle, double initial_work, bool record_trace,
                     int repetition, double sample_interval) {
  CycleResult out;
  out.work = initial_work;
  const std::size_t n = models.size();
  for (std::size_t p = 0; p < n; ++p) {
    sim::TrialOptions options;
    options.initial_work = out.work;
    options.record_trace = record_trace;
    options.repetition = repetition;
    options.sample_interval = sample_interval;
    PartRun run;
    run.start_time = out.time;
    run.start_work = out.work;
    run.trial = sim::RunTrial(*models[p], CycleKey(seed, cycle, n, p), options);
    out.time += run.trial.end_time;
    out.work = run.trial.work;
    const bool done = run.trial.status == sim::Status::kCompleted;
    out.warnings.Add(run.trial.warnings);
    out.numerical_failure = sim::IsComputationFailure(run.trial.status);
    out.parts.push_back(std::move(run));
    if (!done) return out;
  }
  out.completed = true;
  return out;
}

CycleResult RunCycle(const scene::Scene& scene, std::uint64_t seed, std::uint64_t cycle,
                     double initial_work, bool record_trace, int repetition) {
  return RunCycle(sim::BuildSequenceModels(scene), seed, cycle, initial_work,
                  record_trace, repetition);
}

}  // namespace vahf::experiment
