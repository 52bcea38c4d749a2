#include "vahf/kinds/trial_request.h"

#include <fmt/format.h>

#include "vahf/core/error.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial.h"

namespace vahf::kinds {
namespace {

// The scene's file kind, told apart before it is read as a scene: another
// vahf file is named as such, with the command that takes it.
void ExpectSceneFile(const nlohmann::json& document, const std::string& path) {
  const std::string format = scene::FormatOf(document, path);
  if (format == "scene") return;
  const char* what = format == "experiment"
                         ? "an experiment file (run it with `vahf run`)"
                     : format == "lab" ? "a lab dataset (compare or calibrate against it "
                                         "with an experiment file and `vahf run`)"
                     : format == "overrides" ? "a parameter override file (apply it with "
                                               "`vahf run EXPERIMENT --overrides FILE`)"
                                             : "a synthetic lab generator (run it with "
                                               "`vahf synthesize`)";
  scene::JsonNode(document, path)
      .Required("format")
      .Fail(fmt::format("this is {}; `vahf trial` takes a scene file", what));
}

// Command-line text as a parameter's value: JSON (a number), else the text
// itself (a choice's bare name).
nlohmann::json ValueOfText(const std::string& text) {
  nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
  if (value.is_discarded()) value = text;
  return value;
}

// Sets parameter `name` of `scene` to `value` by the parameter table's rule.
void SetParameter(const char* option, const std::string& name,
                  const nlohmann::json& value, scene::Scene* scene) {
  const scene::ParamSpec* spec = scene::FindParam(name);
  if (!spec) throw InputError(option, "", name, "names no parameter (see `vahf params`)");
  scene::ReadParamValue(*spec, scene::JsonNode(value, option, "/" + name),
                        &scene->params);
}

}  // namespace

scene::Scene LoadSceneFile(const std::string& path) {
  const nlohmann::json document = scene::ReadJsonFile(path);
  ExpectSceneFile(document, path);
  return scene::ParseScene(document, path);
}

void SetParameters(const char* option, const ParameterSets& sets, scene::Scene* scene) {
  for (const auto& [name, value] : sets) SetParameter(option, name, value, scene);
}

ParameterSets SplitParameterSets(const std::vector<std::string>& texts) {
  ParameterSets sets;
  for (const std::string& set : texts) {
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos)
      throw InputError("--set", "", set,
                       "takes GROUP/KEY=VALUE, e.g. simulation/max_steps=20000");
    sets.emplace_back(set.substr(0, eq), ValueOfText(set.substr(eq + 1)));
  }
  return sets;
}

sim::TrialResult RunTrialRequest(scene::Scene scene, const std::string& path,
                                 const TrialRequest& a) {
  if (!a.integrator.empty()) scene.params.simulation.integrator = a.integrator;
  if (!a.accuracy.empty())
    SetParameter("--accuracy", "simulation/accuracy", ValueOfText(a.accuracy), &scene);
  SetParameters(a.names.sets, a.sets, &scene);
  if (const std::string v = scene::ParameterViolation(scene); !v.empty())
    throw InputError(a.names.sets, "", "applied to " + path, v);
  if (a.position < 0 || a.position >= static_cast<int>(scene.sequence.size()))
    throw InputError(a.names.position, "", std::to_string(a.position),
                     "must be 0 to " + std::to_string(scene.sequence.size() - 1) +
                         ": the scene's sequence has " +
                         std::to_string(scene.sequence.size()) + " parts");
  sim::TrialOptions options;
  options.sequence_position = a.position;
  options.record_trace = a.record_trace;
  if (a.sample != 0 && !(a.sample > 0 && a.sample <= scene.params.simulation.time_limit))
    throw InputError(a.names.sample, "", fmt::format("{}", a.sample),
                     "must be > 0 s and at most the scene's time_limit");
  if (a.sample > 0 && !a.record_trace)
    throw InputError(a.names.sample, "", fmt::format("{}", a.sample),
                     a.names.trace_needed);
  // Rows are held until the trace is written: 1e6 rows are about 0.5 GB of CSV.
  if (a.sample > 0 && scene.params.simulation.time_limit / a.sample > 1e6)
    throw InputError(
        a.names.sample, "", fmt::format("{}", a.sample),
        fmt::format("at most 1e6 rows over the time limit ({} s): DT >= {} s",
                    scene.params.simulation.time_limit,
                    scene.params.simulation.time_limit / 1e6));
  options.sample_interval = a.sample;
  return sim::RunTrial(scene, {a.seed, a.trial}, options);
}

}  // namespace vahf::kinds
