#include "vahf/experiment/precision_input.h"

#include <fmt/format.h>

#include <memory>

#include "vahf/scene/overrides.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::experiment {

using scene::ExperimentFile;
using scene::FindParam;
using scene::JsonNode;
using scene::LoadScene;
using scene::NumberText;
using scene::Parameters;
using scene::ParameterViolation;
using scene::ParamNames;
using scene::ReadParamValue;
using scene::ResolvePath;
using scene::Scene;

namespace {

std::string ValueText(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return NumberText(v.get<double>());
  return v.dump();
}

// A setting or the reference: an object of "group/key": value, each read by
// the parameter table's rule (on a scratch copy: the scenes get them later).
PrecisionSetting ReadSetting(const JsonNode& node) {
  node.ExpectObject(ParamNames());
  PrecisionSetting s;
  s.pointer = node.path();
  Parameters scratch;
  for (const auto& item : node.json().items()) {
    const JsonNode value = node.Required(item.key());
    ReadParamValue(*FindParam(item.key()), value, &scratch);
    s.overrides.emplace_back(item.key(), item.value());
  }
  s.label = SettingLabel(s.overrides);
  return s;
}

// The scene with the setting's overrides, checked by the rules that tie
// parameters together (the scene loader's); a violation names the setting.
Scene Apply(const Scene& scene, const PrecisionSetting& setting, const JsonNode& node) {
  Scene out = scene;
  for (const auto& [name, value] : setting.overrides)
    ReadParamValue(*FindParam(name), node.Required(name), &out.params);
  const std::string violation = ParameterViolation(out);
  if (!violation.empty())
    node.Fail("applied to scene '" + scene.name + "' (" + scene.file + "): " + violation);
  return out;
}

}  // namespace

void ReadPrecision(const JsonNode& root, const std::string& path, ExperimentFile* e) {
  PrecisionDesign d;
  const JsonNode reference = root.Required("reference");
  d.reference = ReadSetting(reference);
  d.reference.label = "reference: " + d.reference.label;
  const JsonNode settings = root.Required("settings");
  const std::size_t n = settings.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    PrecisionSetting s = ReadSetting(settings.At(k));
    if (s.overrides == d.reference.overrides)
      settings.At(k).Fail("repeats the reference (it is compared with itself anyway)");
    for (const PrecisionSetting& other : d.settings)
      if (other.label == s.label)
        settings.At(k).Fail("repeats the setting at " + other.pointer);
    d.settings.push_back(std::move(s));
  }
  if (auto noise = root.Optional("noise_trials"))
    d.noise_trials = static_cast<int>(noise->Integer(1, 10'000'000));

  const JsonNode scenes = root.Required("scenes");
  const std::size_t m = scenes.ArraySize(1);
  for (std::size_t k = 0; k < m; ++k) {
    const JsonNode entry = scenes.At(k);
    PrecisionScene ps;
    if (entry.json().is_object()) {
      entry.ExpectObject({"scene", "trials"});
      ps.path = ResolvePath(entry.Required("scene"), path, "scene");
      if (auto t = entry.Optional("trials"))
        ps.trials = static_cast<int>(t->Integer(1, 10'000'000));
    } else {
      ps.path = ResolvePath(entry, path, "scene");
    }
    ps.scene = LoadScene(ps.path);
    for (const PrecisionScene& other : d.scenes)
      if (other.scene.name == ps.scene.name)
        entry.Fail("scene names must be unique in a precision experiment ('" +
                   ps.scene.name + "' is also " + other.path + ")");
    ps.reference = Apply(ps.scene, d.reference, reference);
    for (std::size_t s = 0; s < n; ++s)
      ps.settings.push_back(Apply(ps.scene, d.settings[s], settings.At(s)));
    d.scenes.push_back(std::move(ps));
  }
  e->scene_path = d.scenes[0].path;
  e->scene = d.scenes[0].scene;
  e->input =
      core::ClonePtr<scene::KindInput>(std::make_unique<PrecisionDesign>(std::move(d)));
}

void PrecisionDesign::ApplyOverrides(const scene::ParameterOverrides& o,
                                     scene::ExperimentFile* file) {
  for (PrecisionScene& ps : scenes) {
    scene::ApplyOverrides(o, &ps.scene);
    scene::ApplyOverridesExcept(o, reference.overrides, "", &ps.reference);
    for (std::size_t k = 0; k < ps.settings.size(); ++k)
      scene::ApplyOverridesExcept(o, settings[k].overrides, "", &ps.settings[k]);
  }
  if (!scenes.empty()) file->scene = scenes[0].scene;
}

std::vector<std::string> PrecisionDesign::InputFiles() const {
  std::vector<std::string> out;
  for (const PrecisionScene& s : scenes) out.push_back(s.path);
  return out;
}

bool PrecisionSetting::AccuracyOnly() const {
  bool accuracy = false;
  for (const auto& [name, value] : overrides) {
    if (name == "simulation/accuracy") {
      accuracy = true;
    } else if (name != "simulation/integrator") {
      return false;
    }
  }
  return accuracy;
}

std::string SettingLabel(
    const std::vector<std::pair<std::string, nlohmann::json>>& overrides) {
  if (overrides.empty()) return "scene parameters";
  const nlohmann::json* integrator = nullptr;
  const nlohmann::json* accuracy = nullptr;
  for (const auto& [name, value] : overrides) {
    if (name == "simulation/integrator") integrator = &value;
    if (name == "simulation/accuracy") accuracy = &value;
  }
  // Integrator and accuracy together lead as "CVODE 1e-4"; the rest follow.
  const bool paired = integrator && accuracy;
  std::string out = paired ? ValueText(*integrator) + " " + ValueText(*accuracy) : "";
  for (const auto& [name, value] : overrides) {
    if (paired && (&value == integrator || &value == accuracy)) continue;
    out += (out.empty() ? "" : ", ") + name + " " + ValueText(value);
  }
  return out;
}

std::string DescribePrecision(const ExperimentFile& e) {
  const PrecisionDesign& d = e.Input<PrecisionDesign>();
  std::string out = fmt::format(
      "precision: each setting against the reference on common random numbers; Monte "
      "Carlo noise of an experiment with {} cycles per condition\n",
      d.noise_trials);
  out += fmt::format("scenes ({}):\n", d.scenes.size());
  for (const PrecisionScene& s : d.scenes)
    out +=
        fmt::format("  {} ({}): {} part(s), {} cycles per setting\n", s.scene.name,
                    s.path, s.scene.sequence.size(), s.trials > 0 ? s.trials : e.trials);
  const auto overrides = [](const PrecisionSetting& s) {
    std::string o;
    for (const auto& [name, value] : s.overrides)
      o += fmt::format("{}{} = {}", o.empty() ? "" : ", ", name, value.dump());
    return o.empty() ? std::string("(none)") : o;
  };
  out += fmt::format("{} ({}): {}\n", d.reference.label, d.reference.pointer,
                     overrides(d.reference));
  out += fmt::format("settings ({}):\n", d.settings.size());
  for (const PrecisionSetting& s : d.settings)
    out += fmt::format("  {:<32} ({}): {}\n", s.label, s.pointer, overrides(s));
  return out;
}

}  // namespace vahf::experiment
