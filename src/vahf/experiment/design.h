// The paper's experiments as designs over cycles (docs/design.md, "Experiments"):
// each runs `trials` cycles (cycle.h) under each of its conditions on the
// runner's thread pool. Cycle j of every condition uses the same streams
// (common random numbers), so conditions differ by what defines them only.
//
//   table1                one condition: the scene;
//   assembly_time         one condition per operator (Sec. 5.2);
//   human_factors_groups  one condition per working condition (Sec. 5.3);
//   fatigue               a pilot at A = 0 that measures the operator's work
//                         rate, then one condition per segment of the hour
//                         (Sec. 5.4), see RunExperiment;
//   precision             per scene, the reference and one condition per
//                         setting of the integrator or model (precision_design.h);
//   paper                 each experiment it lists (kinds/paper_kind.cc).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "vahf/experiment/cycle.h"
#include "vahf/experiment/runner.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/shared_inputs.h"

namespace vahf::experiment {

struct Condition {
  std::string name;   // operator, working condition, segment or precision setting
  std::string group;  // an operator's sex; a precision setting's scene; else empty
  std::shared_ptr<const scene::Scene> scene;
  int trials = 0;  // > 0: this condition's cycles instead of RunDesign's `trials`
  // Added to the cycles' stream indices: 0 shares streams with the other
  // conditions (common random numbers, the default); a lab's operators are
  // different people and draw their own (calibrate/targets.h).
  std::uint64_t cycle_offset = 0;
  // Cycle j of N starts at minute start + (end - start) (j + 0.5) / N of the
  // operator's working time, with the work A done by then (fatigue; else 0).
  double minute_start = 0, minute_end = 0;
  double work_start = 0, work_end = 0;
  // > 0: the condition is an operator repeating the task, cycle j of it the
  // operator's repetition (j mod repetitions) + 1 (human/learning.h; with
  // `trials` a multiple of it, each repetition has as many cycles). 0: every
  // cycle is a first repetition.
  int repetitions = 0;
  int RepetitionOf(std::size_t j) const {
    return repetitions > 0
               ? static_cast<int>(j % static_cast<std::size_t>(repetitions)) + 1
               : 1;
  }
};

// The condition of one operator (Sec. 5.2): the scene with the operator's
// sex, stature and arm length, standing where the scene's operator stands.
Condition OperatorCondition(const scene::Scene& scene, const scene::OperatorEntry& op);

struct CycleRecord {
  std::size_t condition = 0;  // index into DesignRun::conditions
  std::uint64_t cycle = 0;    // j: the stream index of the cycle
  double start_minute = 0;
  double initial_work = 0;  // J
  int repetition = 1;       // the operator's repetition (Condition::RepetitionOf)
  CycleResult result;
};

struct DesignRun {
  std::vector<Condition> conditions;
  std::vector<CycleRecord> records;  // condition-major, then cycle: fixed order
};

// Runs `trials` cycles of every condition (or the condition's own `trials`),
// with stream indices first_cycle, first_cycle + 1, ... Same inputs: the same
// records, whatever options.threads.
DesignRun RunDesign(std::vector<Condition> conditions, int trials, std::uint64_t seed,
                    bool record_trace, const RunnerOptions& options,
                    std::uint64_t first_cycle = 0);

// The fatigue design (Sec. 5.4; see RunExperiment): a pilot of cycles from
// A = 0 measures the work rate w (J per second of cycle time); segment s of S
// covers minutes [s, s + 1) * duration / S, and its `trials` cycles start with
// the work w * 60 * minute that back-to-back cycles would have accumulated by
// their minute. `only` lists the 0-based segments to run (empty: all), in
// increasing order; a segment's cycles are the same whichever others run.
// Its segments draw from the stream indices first_cycle, first_cycle + 1,
// ..., the pilot from first_cycle + trials on (a design run beside another
// shifts them past the other's).
struct FatigueRun {
  DesignRun pilot;
  double work_rate = 0;
  DesignRun run;              // one condition per segment run, in segment order
  std::vector<int> segments;  // the 0-based segment of each condition of `run`
};
FatigueRun RunFatigue(const std::shared_ptr<const scene::Scene>& scene,
                      const scene::FatigueDesign& design, int trials, std::uint64_t seed,
                      const RunnerOptions& options, const RunnerOptions& pilot_options,
                      const std::vector<int>& only = {}, std::uint64_t first_cycle = 0);

struct RunSettings {
  std::uint64_t seed = 1;
  int trials = 0;  // > 0 overrides the experiment file's
  int threads = 1;
  bool progress = true;
  ProgressSink* progress_sink = nullptr;  // progress.h; null: none
  Journal* journal = nullptr;             // the run's journal (journal.h); null: none
  const Ranks* ranks =
      nullptr;  // the processes it is spread over (ranks.h); null: this one
  int RankCount() const { return ranks ? ranks->size() : 1; }
};

// The runner's options of a run with these settings (threads, progress,
// journal, ranks), its indices called `unit` on the progress line of `label`.
RunnerOptions RunnerOptionsOf(const RunSettings& settings, const std::string& label,
                              const std::string& unit = "cycles");

struct ExperimentRun {
  const scene::ExperimentFile* file = nullptr;
  std::uint64_t seed = 1;
  int trials = 1;  // cycles per condition; paper: the override, 0 if none (see parts)
  DesignRun run;
  // fatigue: the pilot cycles from A = 0, and the work rate they measured,
  // J per second of assembly (total work over total cycle time).
  DesignRun pilot;
  double work_rate = 0;
  std::vector<ExperimentRun> parts;  // paper: one run per listed experiment
};

// The design of each kind of experiment that is a design of cycles (the kind
// registry, kinds/kind.h, names them; a paper run is its experiments' runs).
// Fatigue: the operator works cycles back to back for duration_min; segment s
// of S covers minutes [s, s + 1) * duration / S. Simulating every cycle of an
// hour one after another would take hours, so the design is stratified: a
// pilot of cycles started at A = 0 measures the mean work rate w (J/s of
// cycle time), and each segment's `trials` cycles are spread evenly over its
// minutes, cycle j starting with the work A = w * 60 * minute that
// back-to-back cycles would have accumulated by then (RunFatigue).
ExperimentRun Table1Run(const scene::ExperimentFile& file, const RunSettings& settings);
ExperimentRun AssemblyTimeRun(const scene::ExperimentFile& file,
                              const RunSettings& settings);
ExperimentRun HumanFactorsGroupsRun(const scene::ExperimentFile& file,
                                    const RunSettings& settings);
ExperimentRun FatigueExperimentRun(const scene::ExperimentFile& file,
                                   const RunSettings& settings);
ExperimentRun PrecisionRun(const scene::ExperimentFile& file,
                           const RunSettings& settings);

// The conditions of each design, as its run builds them and its cycles
// tables name them, without what only running gives (a fatigue segment's
// work, measured by the pilot): what `vahf replay` needs to run one cycle
// again (docs/reproducibility.md, "Replay"). Fatigue's are its pilot's, then
// its segments'.
std::vector<Condition> Table1Conditions(const scene::ExperimentFile& file,
                                        const RunSettings& settings);
std::vector<Condition> AssemblyTimeConditions(const scene::ExperimentFile& file,
                                              const RunSettings& settings);
std::vector<Condition> HumanFactorsGroupsConditions(const scene::ExperimentFile& file,
                                                    const RunSettings& settings);
std::vector<Condition> FatigueConditions(const scene::ExperimentFile& file,
                                         const RunSettings& settings);
// RunFatigue's conditions: its pilot's, then its segments' without work.
std::vector<Condition> FatigueDesignConditions(
    const std::shared_ptr<const scene::Scene>& scene, const scene::FatigueDesign& design);

}  // namespace vahf::experiment
