#include "vahf/calibrate/synthetic_lab.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>

#include "vahf/core/error.h"
#include "vahf/experiment/design.h"
#include "vahf/rng/stream.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {

SyntheticLabSpec LoadSyntheticLabSpec(const std::string& path) {
  const nlohmann::json document = scene::ReadJsonFile(path);
  const scene::JsonNode root(document, path);
  if (!document.is_object()) root.Fail("a vahf file is a JSON object");
  root.ExpectObject({"format", "name", "description", "scene", "parameters", "operators",
                     "repetitions", "seed", "noise", "condition"});
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
  if (auto params = root.Optional("parameters")) {
    params->ExpectObject(scene::ParamNames());
    for (const auto& item : params->json().items()) {
      const scene::JsonNode value = params->Required(item.key());
      const scene::ParamSpec& p = *scene::FindParam(item.key());
      if (!p.real && p.rule != scene::ParamRule::kChoice)
        value.Fail("a synthetic lab states real-valued parameters and choices");
      scene::ReadParamValue(p, value, &spec.scene.params);
      if (p.real)
        spec.truth.emplace_back(item.key(), p.real(spec.scene.params));
      else
        spec.choices.emplace_back(item.key(), value.String());
    }
    const std::string violation = scene::ParameterViolation(spec.scene);
    if (!violation.empty())
      params->Fail("applied to scene '" + spec.scene.name + "': " + violation);
  }
  // A lab records who assembled: each operator's sex, stature and arm length.
  spec.operators = scene::ReadOperators(root.Required("operators"), spec.scene);
  if (auto r = root.Optional("repetitions"))
    spec.repetitions = static_cast<int>(r->Integer(1, 100'000));
  if (auto seed = root.Optional("seed")) spec.seed = seed->Unsigned();
  if (auto c = root.Optional("condition")) spec.condition = c->String();
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
  std::vector<experiment::Condition> conditions;
  // Operators are different people: each draws from its own cycle indices.
  for (const scene::OperatorEntry& op : spec.operators) {
    conditions.push_back(experiment::OperatorCondition(spec.scene, op));
    conditions.back().cycle_offset = static_cast<std::uint64_t>(conditions.size() - 1) *
                                     static_cast<std::uint64_t>(spec.repetitions);
    conditions.back().repetitions = spec.repetitions;  // cycle j: repetition j + 1
  }
  VAHF_CHECK(!conditions.empty(), "a synthetic lab has operators");
  const experiment::DesignRun run =
      experiment::RunDesign(conditions, spec.repetitions, spec.seed, false, options);

  data::LabDataset lab;
  lab.name = spec.name;
  lab.description = spec.description;
  std::string truth;
  for (const auto& [name, value] : spec.choices)
    truth += fmt::format("{}{} = {}", truth.empty() ? "" : ", ", name, value);
  for (const auto& [name, value] : spec.truth)
    truth += fmt::format("{}{} = {}", truth.empty() ? "" : ", ", name, value);
  lab.provenance = {
      {"source", fmt::format("synthetic: vahf synthesize {} (scene {}, seed {})",
                             spec.file, spec.scene.name, spec.seed)},
      {"notes", fmt::format("the model at {}; {} repetitions per operator; reading error "
                            "sd {} s, times rounded to {} s",
                            truth.empty() ? "the scene's parameters" : truth,
                            spec.repetitions, spec.time_sd, spec.time_resolution)}};
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
      t.condition = spec.condition;
      t.part = p.trial.part;
      t.repetition = r.repetition;
      t.success = p.trial.status == sim::Status::kCompleted;
      t.time = std::numeric_limits<double>::quiet_NaN();
      // Each row has its own noise stream: a row's error does not depend on
      // how many rows came before it.
      rng::Stream noise({spec.seed, row++}, 0, rng::Purpose::kMeasurementNoise);
      const double error = spec.time_sd * noise.Normal();
      if (t.success) {
        double time = p.trial.completion_time + error;
        if (spec.time_resolution > 0)
          time = std::round(time / spec.time_resolution) * spec.time_resolution;
        // A reading error cannot make a time vanish: at least one clock tick.
        t.time = std::max(time, spec.time_resolution > 0 ? spec.time_resolution : 1e-6);
      }
      lab.trials.push_back(std::move(t));
    }
  }
  return lab;
}

}  // namespace vahf::calibrate
