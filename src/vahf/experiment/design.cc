#include "vahf/experiment/design.h"

#include <fmt/format.h>

#include <algorithm>

#include "vahf/core/error.h"
#include "vahf/experiment/assembly_time_input.h"
#include "vahf/experiment/fatigue_input.h"
#include "vahf/experiment/groups_input.h"
#include "vahf/experiment/precision_design.h"
#include "vahf/experiment/result_codec.h"

namespace vahf::experiment {

DesignRun RunDesign(std::vector<Condition> conditions, int trials, std::uint64_t seed,
                    bool record_trace, const RunnerOptions& options,
                    std::uint64_t first_cycle) {
  VAHF_CHECK(trials >= 1, "at least one cycle per condition");
  DesignRun out;
  out.conditions = std::move(conditions);
  // Condition c's cycles are indices [first[c], first[c + 1]) of the run.
  std::vector<std::size_t> first = {0};
  for (const Condition& c : out.conditions)
    first.push_back(first.back() +
                    static_cast<std::size_t>(c.trials > 0 ? c.trials : trials));
  const auto& conds = out.conditions;
  // Every scene's trial models, built once before any cycle runs (a scene
  // only building can reject fails here, with nothing lost) and shared by
  // the conditions that run it.
  std::vector<std::shared_ptr<const SequenceModels>> models;
  for (std::size_t c = 0; c < conds.size(); ++c) {
    std::shared_ptr<const SequenceModels> built;
    for (std::size_t e = 0; e < c && !built; ++e)
      if (conds[e].scene == conds[c].scene) built = models[e];
    if (!built)
      built = std::make_shared<const SequenceModels>(
          sim::BuildSequenceModels(*conds[c].scene));
    models.push_back(built);
  }
  const std::function<CycleRecord(std::size_t)> cycle = [&](std::size_t k) {
    CycleRecord r;
    r.condition = static_cast<std::size_t>(
        std::upper_bound(first.begin(), first.end(), k) - first.begin() - 1);
    const std::size_t j = k - first[r.condition];
    const std::size_t n = first[r.condition + 1] - first[r.condition];
    r.cycle = first_cycle + conds[r.condition].cycle_offset + j;
    const Condition& c = conds[r.condition];
    const double u = (static_cast<double>(j) + 0.5) / static_cast<double>(n);
    r.start_minute = c.minute_start + (c.minute_end - c.minute_start) * u;
    r.initial_work = c.work_start + (c.work_end - c.work_start) * u;
    r.repetition = c.RepetitionOf(j);
    r.result = RunCycle(*models[r.condition], seed, r.cycle, r.initial_work, record_trace,
                        r.repetition);
    return r;
  };
  out.records = RunIndexed<CycleRecord>(first.back(), options, cycle, &kCycleRecordCodec);
  return out;
}

RunnerOptions RunnerOptionsOf(const RunSettings& s, const std::string& label,
                              const std::string& unit) {
  RunnerOptions o;
  o.threads = s.threads;
  o.label = label;
  o.unit = unit;
  o.progress = s.progress;
  o.progress_sink = s.progress_sink;
  o.journal = s.journal;
  o.ranks = s.ranks;
  return o;
}

namespace {

std::shared_ptr<const scene::Scene> Share(const scene::Scene& s) {
  return std::make_shared<const scene::Scene>(s);
}

}  // namespace

Condition OperatorCondition(const scene::Scene& scene, const scene::OperatorEntry& op) {
  scene::Scene s = scene;
  s.op.height = op.height;
  s.op.arm_length = op.arm_length;
  s.op.sex = op.sex;
  return {op.name, op.sex, Share(s)};
}

namespace {

// Segment s of the hour, without its work (the pilot measures the rate).
Condition FatigueSegment(const std::shared_ptr<const scene::Scene>& scene,
                         const scene::FatigueDesign& f, int s) {
  const double per_segment = f.duration_min / f.segments;
  Condition c;
  c.name = fmt::format("{:g}-{:g} min", s * per_segment, (s + 1) * per_segment);
  c.scene = scene;
  c.minute_start = s * per_segment;
  c.minute_end = (s + 1) * per_segment;
  return c;
}

const char* const kPilot = "pilot";

}  // namespace

FatigueRun RunFatigue(const std::shared_ptr<const scene::Scene>& scene,
                      const scene::FatigueDesign& f, int trials, std::uint64_t seed,
                      const RunnerOptions& options, const RunnerOptions& pilot_options,
                      const std::vector<int>& only, std::uint64_t first_cycle) {
  FatigueRun out;
  const int pilot = f.pilot_cycles > 0 ? f.pilot_cycles : trials;
  // The pilot's streams are its own: cycle indices after every segment's.
  out.pilot = RunDesign({{kPilot, "", scene}}, pilot, seed, false, pilot_options,
                        first_cycle + static_cast<std::uint64_t>(trials));
  double work = 0, time = 0;
  for (const CycleRecord& r : out.pilot.records) {
    work += r.result.work - r.initial_work;
    time += r.result.time;
  }
  out.work_rate = time > 0 ? work / time : 0.0;
  std::vector<Condition> conditions;
  for (int s = 0; s < f.segments; ++s) {
    if (!only.empty() && std::find(only.begin(), only.end(), s) == only.end()) continue;
    Condition c = FatigueSegment(scene, f, s);
    c.work_start = out.work_rate * 60.0 * c.minute_start;
    c.work_end = out.work_rate * 60.0 * c.minute_end;
    conditions.push_back(c);
    out.segments.push_back(s);
  }
  out.run = RunDesign(conditions, trials, seed, false, options, first_cycle);
  return out;
}

namespace {

// A run of `file` with the settings' seed and cycles, before its design runs.
ExperimentRun Begin(const scene::ExperimentFile& file, const RunSettings& settings) {
  ExperimentRun out;
  out.file = &file;
  out.seed = settings.seed;
  out.trials = settings.trials > 0 ? settings.trials : file.trials;
  return out;
}

RunnerOptions Options(const scene::ExperimentFile& file, const RunSettings& settings) {
  return RunnerOptionsOf(settings, file.name + " (" + file.kind + ")");
}

}  // namespace

std::vector<Condition> Table1Conditions(const scene::ExperimentFile& file,
                                        const RunSettings&) {
  return {{file.scene.name, "", Share(file.scene)}};
}

ExperimentRun Table1Run(const scene::ExperimentFile& file, const RunSettings& settings) {
  ExperimentRun out = Begin(file, settings);
  out.run = RunDesign(Table1Conditions(file, settings), out.trials, out.seed, true,
                      Options(file, settings));
  return out;
}

std::vector<Condition> AssemblyTimeConditions(const scene::ExperimentFile& file,
                                              const RunSettings& settings) {
  const std::vector<scene::OperatorEntry>& operators =
      file.Input<AssemblyTimeInput>().operators;
  std::vector<Condition> conditions;
  if (operators.empty())
    conditions.push_back({"scene operator", file.scene.op.sex, Share(file.scene)});
  for (const scene::OperatorEntry& o : operators)
    conditions.push_back(OperatorCondition(file.scene, o));
  // Each operator assembles the sequence `trials` times over (Sec. 5.2: ten
  // real assemblies each): cycle j is their repetition j + 1.
  for (Condition& c : conditions) c.repetitions = Begin(file, settings).trials;
  return conditions;
}

ExperimentRun AssemblyTimeRun(const scene::ExperimentFile& file,
                              const RunSettings& settings) {
  ExperimentRun out = Begin(file, settings);
  out.run = RunDesign(AssemblyTimeConditions(file, settings), out.trials, out.seed, false,
                      Options(file, settings));
  return out;
}

std::vector<Condition> HumanFactorsGroupsConditions(const scene::ExperimentFile& file,
                                                    const RunSettings&) {
  std::vector<Condition> conditions;
  for (const ConditionEntry& c : file.Input<GroupsInput>().conditions)
    conditions.push_back({c.name, "", Share(c.scene)});
  return conditions;
}

ExperimentRun HumanFactorsGroupsRun(const scene::ExperimentFile& file,
                                    const RunSettings& settings) {
  ExperimentRun out = Begin(file, settings);
  out.run = RunDesign(HumanFactorsGroupsConditions(file, settings), out.trials, out.seed,
                      true, Options(file, settings));
  return out;
}

std::vector<Condition> FatigueDesignConditions(
    const std::shared_ptr<const scene::Scene>& scene,
    const scene::FatigueDesign& design) {
  std::vector<Condition> conditions = {{kPilot, "", scene}};
  for (int s = 0; s < design.segments; ++s)
    conditions.push_back(FatigueSegment(scene, design, s));
  return conditions;
}

std::vector<Condition> FatigueConditions(const scene::ExperimentFile& file,
                                         const RunSettings&) {
  return FatigueDesignConditions(Share(file.scene), file.Input<FatigueInput>().fatigue);
}

ExperimentRun FatigueExperimentRun(const scene::ExperimentFile& file,
                                   const RunSettings& settings) {
  ExperimentRun out = Begin(file, settings);
  FatigueRun f = RunFatigue(Share(file.scene), file.Input<FatigueInput>().fatigue,
                            out.trials, out.seed, Options(file, settings),
                            RunnerOptionsOf(settings, file.name + " (fatigue pilot)"));
  out.pilot = std::move(f.pilot);
  out.work_rate = f.work_rate;
  out.run = std::move(f.run);
  return out;
}

ExperimentRun PrecisionRun(const scene::ExperimentFile& file,
                           const RunSettings& settings) {
  ExperimentRun out = Begin(file, settings);
  out.run = RunDesign(PrecisionConditions(file, settings.trials), out.trials, out.seed,
                      false, Options(file, settings));
  return out;
}

}  // namespace vahf::experiment
