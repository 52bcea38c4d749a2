#include "vahf/calibrate/synthetic_lab.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/experiment/design.h"
#include "vahf/rng/stream.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {

namespace {

// Stated parameter values (an object of "group/key": value) set in `scene`
// and appended to `values`: real-valued parameters of the table, whose rules
// the scene must then obey.
void ReadStatedValues(const scene::JsonNode& params, scene::Scene* scene,
                      std::vector<std::pair<std::string, double>>* values,
                      std::vector<std::pair<std::string, std::string>>* choices) {
  params.ExpectObject(scene::ParamNames());
  for (const auto& item : params.json().items()) {
    const scene::JsonNode value = params.Required(item.key());
    const scene::ParamSpec& p = *scene::FindParam(item.key());
    if (!p.real && p.rule != scene::ParamRule::kChoice)
      value.Fail("a synthetic lab states real-valued parameters and choices");
    scene::ReadParamValue(p, value, &scene->params);
    if (p.real)
      values->emplace_back(item.key(), p.real(scene->params));
    else
      choices->emplace_back(item.key(), value.String());
  }
  const std::string violation = scene::ParameterViolation(*scene);
  if (!violation.empty())
    params.Fail("applied to scene '" + scene->name + "': " + violation);
}

// "conditions": [{"name", "scene", "parameters"}, ...], each the generator's
// scene or its own with the truth and then its own values; every operator
// must fit each condition's reach curve.
std::vector<SyntheticCondition> ReadConditions(const scene::JsonNode& list,
                                               const SyntheticLabSpec& spec,
                                               const std::string& path) {
  std::vector<SyntheticCondition> out;
  const std::size_t n = list.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const scene::JsonNode c = list.At(k);
    c.ExpectObject({"name", "scene", "parameters"});
    SyntheticCondition entry;
    const scene::JsonNode name = c.Required("name");
    entry.name = name.String();
    // trials.csv's rule: a condition is named.
    if (entry.name.empty()) name.Fail("a condition has a name (not empty)");
    for (const SyntheticCondition& other : out)
      if (other.name == entry.name) name.Fail("condition names must be unique");
    entry.scene = spec.scene;
    if (auto own = c.Optional("scene")) {
      entry.scene_path = scene::ResolvePath(*own, path, "scene");
      entry.scene = scene::LoadScene(entry.scene_path);
      // The stated values hold in every condition; its own come after them.
      for (const auto& [key, value] : spec.truth)
        scene::FindParam(key)->real(entry.scene.params) = value;
      for (const auto& [key, value] : spec.choices)
        scene::FindParam(key)->text(entry.scene.params) = value;
      const std::string violation = scene::ParameterViolation(entry.scene);
      if (!violation.empty()) own->Fail("with the generator's parameters: " + violation);
    }
    if (auto params = c.Optional("parameters")) {
      std::vector<std::pair<std::string, std::string>> choices;
      ReadStatedValues(*params, &entry.scene, &entry.parameters, &choices);
      if (!choices.empty())
        params->Required(choices.front().first)
            .Fail("a condition states real-valued parameters; a choice is the scene's");
    }
    for (const scene::OperatorEntry& op : spec.operators) {
      const std::string reach =
          entry.scene.params.reach.Violation(op.arm_length, op.height);
      if (!reach.empty()) name.Fail("operator " + op.name + ": " + reach);
    }
    out.push_back(std::move(entry));
  }
  return out;
}

// "fatigue": the hour of work's design, as the fatigue kind reads it, and
// the cycles each segment records.
SyntheticFatigue ReadSyntheticFatigue(const scene::JsonNode& f) {
  SyntheticFatigue out;
  out.design = scene::ReadFatigueObject(f, {"trials"});
  out.trials = static_cast<int>(f.Required("trials").Integer(1, 100'000));
  return out;
}

// The working conditions: the generator's list, or one, `condition`, on its
// scene.
std::vector<SyntheticCondition> ConditionsOf(const SyntheticLabSpec& spec) {
  if (!spec.conditions.empty()) return spec.conditions;
  SyntheticCondition only;
  only.name = spec.condition;
  only.scene = spec.scene;
  return {only};
}

// One design condition per working condition and operator, condition-major
// (`names[i]`: condition i's working condition). Operators are different
// people: each draws from its own cycle indices, in every working condition.
std::vector<experiment::Condition> TrialConditions(const SyntheticLabSpec& spec,
                                                   std::vector<std::string>* names) {
  std::vector<experiment::Condition> out;
  for (const SyntheticCondition& w : ConditionsOf(spec))
    for (const scene::OperatorEntry& op : spec.operators) {
      out.push_back(experiment::OperatorCondition(w.scene, op));
      out.back().cycle_offset = static_cast<std::uint64_t>(out.size() - 1) *
                                static_cast<std::uint64_t>(spec.repetitions);
      out.back().repetitions = spec.repetitions;  // cycle j: repetition j + 1
      names->push_back(w.name);
    }
  return out;
}

// A time as the lab's clock reads it: plus a Gaussian reading error from row
// `row`'s own stream, rounded to the clock's resolution, and at least one
// tick (a reading error cannot make a time vanish).
double ReadTime(const SyntheticLabSpec& spec, std::uint64_t row, double time) {
  rng::Stream noise({spec.seed, row}, 0, rng::Purpose::kMeasurementNoise);
  double read = time + spec.time_sd * noise.Normal();
  if (spec.time_resolution > 0)
    read = std::round(read / spec.time_resolution) * spec.time_resolution;
  return std::max(read, spec.time_resolution > 0 ? spec.time_resolution : 1e-6);
}

// What the notes add to the trials' description: the conditions' own
// values and the hour of work.
std::string ExtraNotes(const SyntheticLabSpec& spec) {
  std::string out;
  for (const SyntheticCondition& c : spec.conditions) {
    std::string own;
    for (const auto& [name, value] : c.parameters)
      own += fmt::format("{}{} = {}", own.empty() ? "" : ", ", name, value);
    out += fmt::format("; condition {}: {}{}", c.name,
                       c.scene_path.empty() ? "the generator's scene" : c.scene_path,
                       own.empty() ? "" : " at " + own);
  }
  const SyntheticFatigue& f = spec.fatigue;
  if (f.trials > 0)
    out += fmt::format(
        "; segments.csv: the scene's operator works {} min in {} segments of {} "
        "cycles each (pilot of {} cycles), each condition its own hour",
        f.design.duration_min, f.design.segments, f.trials,
        f.design.pilot_cycles > 0 ? f.design.pilot_cycles : f.trials);
  return out;
}

// segments.csv: each working condition's hour of work (experiment::RunFatigue
// on its scene, the scene's operator working), on stream indices after the
// `trial_cycles` the trials used, condition c from c x (trials + pilot) on.
// A segment's attempts are its cycles that were not failures of the
// computation (as a calibration's virtual side counts them), its mean time
// that of its successes' read times (rows from `row` on). A segment without
// an attempt is not recorded (segments.csv requires one).
void AddSegments(const SyntheticLabSpec& spec, const experiment::RunnerOptions& options,
                 std::uint64_t trial_cycles, std::uint64_t row, data::LabDataset* lab) {
  const SyntheticFatigue& f = spec.fatigue;
  if (f.trials <= 0) return;
  const int pilot = f.design.pilot_cycles > 0 ? f.design.pilot_cycles : f.trials;
  const std::uint64_t span = static_cast<std::uint64_t>(f.trials + pilot);
  const std::vector<SyntheticCondition> conditions = ConditionsOf(spec);
  int line = 1;
  for (std::size_t c = 0; c < conditions.size(); ++c) {
    const experiment::FatigueRun hour = experiment::RunFatigue(
        std::make_shared<const scene::Scene>(conditions[c].scene), f.design, f.trials,
        spec.seed, options, options, {}, trial_cycles + c * span);
    for (std::size_t k = 0; k < hour.run.conditions.size(); ++k) {
      const experiment::Condition& segment = hour.run.conditions[k];
      data::LabSegment s;
      s.segment = hour.segments[k] + 1;
      s.start_min = segment.minute_start;
      s.end_min = segment.minute_end;
      s.condition = conditions[c].name;
      double sum = 0;
      for (const experiment::CycleRecord& r : hour.run.records) {
        if (r.condition != k) continue;
        const double read = ReadTime(spec, row++, r.result.time);
        if (r.result.numerical_failure) continue;
        ++s.attempts;
        if (!r.result.completed) continue;
        ++s.successes;
        sum += read;
      }
      if (s.successes > 0) s.mean_time = sum / s.successes;
      s.line = ++line;
      if (s.attempts > 0) lab->segments.push_back(s);
    }
  }
  if (!lab->segments.empty()) lab->segments_file = "segments.csv";
}

}  // namespace

SyntheticLabSpec LoadSyntheticLabSpec(const std::string& path) {
  const nlohmann::json document = scene::ReadJsonFile(path);
  const scene::JsonNode root(document, path);
  if (!document.is_object()) root.Fail("a vahf file is a JSON object");
  root.ExpectObject({"format", "name", "description", "scene", "parameters", "operators",
                     "repetitions", "seed", "noise", "condition", "conditions",
                     "fatigue"});
  const scene::JsonNode format = root.Required("format");
  if (format.String() != scene::kSyntheticFormat)
    format.Fail(std::string("a synthetic lab generator declares \"format\": \"") +
                scene::kSyntheticFormat + "\"");
  SyntheticLabSpec spec;
  spec.file = path;
  spec.name = root.Required("name").String();
  if (auto d = root.Optional("description")) spec.description = d->String();
  spec.scene_path = scene::ResolvePath(root.Required("scene"), path, "scene");
  spec.scene = scene::LoadScene(spec.scene_path);
  if (auto params = root.Optional("parameters"))
    ReadStatedValues(*params, &spec.scene, &spec.truth, &spec.choices);
  // A lab records who assembled: each operator's sex, stature and arm length.
  spec.operators = scene::ReadOperators(root.Required("operators"), spec.scene);
  if (auto r = root.Optional("repetitions"))
    spec.repetitions = static_cast<int>(r->Integer(1, 100'000));
  if (auto seed = root.Optional("seed")) spec.seed = seed->Unsigned();
  if (auto c = root.Optional("condition")) spec.condition = c->String();
  if (auto list = root.Optional("conditions")) {
    if (root.Optional("condition"))
      list->Fail("a generator names one \"condition\" or lists \"conditions\", not both");
    spec.conditions = ReadConditions(*list, spec, path);
  }
  if (auto f = root.Optional("fatigue")) spec.fatigue = ReadSyntheticFatigue(*f);
  if (auto noise = root.Optional("noise")) {
    noise->ExpectObject({"time_sd", "time_resolution"});
    // Reading errors beyond a minute are not a clock's: a mistake in units.
    if (auto sd = noise->Optional("time_sd")) spec.time_sd = sd->InRange(0, 60);
    if (auto res = noise->Optional("time_resolution"))
      spec.time_resolution = res->InRange(0, 60);
  }
  return spec;
}

data::LabDataset GenerateSyntheticLab(const SyntheticLabSpec& spec,
                                      const experiment::RunnerOptions& options) {
  std::vector<std::string> condition_names;
  const std::vector<experiment::Condition> conditions =
      TrialConditions(spec, &condition_names);
  VAHF_CHECK(!conditions.empty(), "a synthetic lab has operators");
  const experiment::DesignRun run =
      experiment::RunDesign(conditions, spec.repetitions, spec.seed, false, options);

  data::LabDataset lab;
  lab.name = spec.name;
  // A lab dataset says what it holds; a generator need not.
  lab.description = !spec.description.empty()
                        ? spec.description
                        : fmt::format(
                              "A synthetic lab: the model at stated values "
                              "plays the lab (generator {}).",
                              spec.name);
  std::string truth;
  for (const auto& [name, value] : spec.choices)
    truth += fmt::format("{}{} = {}", truth.empty() ? "" : ", ", name, value);
  for (const auto& [name, value] : spec.truth)
    truth += fmt::format("{}{} = {}", truth.empty() ? "" : ", ", name, value);
  lab.provenance = {
      {"source", fmt::format("synthetic: vahf synthesize {} (scene {}, seed {})",
                             spec.file, spec.scene.name, spec.seed)},
      {"notes",
       fmt::format("the model at {}; {} repetitions per operator; reading error "
                   "sd {} s, times rounded to {} s{}",
                   truth.empty() ? "the scene's parameters" : truth, spec.repetitions,
                   spec.time_sd, spec.time_resolution, ExtraNotes(spec))}};
  lab.trials_file = "trials.csv";
  std::uint64_t row = 0;
  for (const experiment::CycleRecord& r : run.records) {
    const experiment::Condition& c = run.conditions[r.condition];
    const scene::Scene& s = *c.scene;
    for (const experiment::PartRun& p : r.result.parts) {
      data::LabTrial t;
      t.operator_id = c.name;
      t.sex = s.op.sex;
      t.height = s.op.height;
      t.arm_length = s.op.arm_length;
      t.condition = condition_names[r.condition];
      t.part = p.trial.part;
      t.repetition = r.repetition;
      t.success = p.trial.status == sim::Status::kCompleted;
      t.time = std::numeric_limits<double>::quiet_NaN();
      // Each row has its own noise stream: a row's error does not depend on
      // how many rows came before it.
      const double read = ReadTime(spec, row++, p.trial.completion_time);
      if (t.success) t.time = read;
      lab.trials.push_back(std::move(t));
    }
  }
  AddSegments(spec, options,
              conditions.size() * static_cast<std::uint64_t>(spec.repetitions), row,
              &lab);
  return lab;
}

}  // namespace vahf::calibrate
