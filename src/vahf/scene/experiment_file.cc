#include "vahf/scene/experiment_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/scene/stepper_catalogue.h"

namespace vahf::scene {

std::string ResolvePath(const JsonNode& node, const std::string& experiment_path,
                        const char* what) {
  const std::filesystem::path relative = node.String();
  const std::string resolved =
      relative.is_absolute()
          ? relative.string()
          : (std::filesystem::path(experiment_path).parent_path() / relative).string();
  std::error_code error;  // e.g. a name longer than the file system allows
  const bool found = std::filesystem::is_regular_file(resolved, error);
  if (error && error != std::errc::no_such_file_or_directory)
    node.Fail(fmt::format("cannot be a {} file's path: {}", what, error.message()));
  // The path as the message shows it: a long one keeps both ends.
  const std::string shown =
      resolved.size() <= 200
          ? resolved
          : resolved.substr(0, 120) + "..." + resolved.substr(resolved.size() - 60);
  if (!found)
    node.Fail(std::string("no ") + what + " file at " + shown +
              " (a relative path is taken from the experiment file's folder)");
  return resolved;
}

std::vector<OperatorEntry> ReadOperators(const JsonNode& node, const Scene& scene) {
  std::vector<OperatorEntry> out;
  const std::size_t n = node.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const JsonNode o = node.At(k);
    o.ExpectObject({"name", "sex", "height", "arm_length", "source"});
    OperatorEntry e;
    e.name = o.Required("name").String();
    e.sex = o.Required("sex").Choice({"male", "female"});
    // The bounds of the scene file's operator (scene_loader.cc).
    e.height = o.Required("height").InRange(1.0, 2.5);
    e.arm_length = o.Required("arm_length").InRange(0.3, 1.2);
    if (auto source = o.Optional("source")) e.source = source->String();
    const std::string reach = scene.params.reach.Violation(e.arm_length, e.height);
    if (!reach.empty()) o.Fail(reach);
    for (const OperatorEntry& other : out)
      if (other.name == e.name) o.Required("name").Fail("operator names must be unique");
    out.push_back(e);
  }
  return out;
}

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
  PrecisionDesign& d = e->precision;
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
}

namespace {

// A fitted parameter's value must obey the parameter table's rule, and so
// must the points a central difference visits around it.
void CheckFitValue(const ParamSpec& spec, const JsonNode& node, double value,
                   double step) {
  Parameters scratch;
  try {
    ReadParamValue(spec, JsonNode(nlohmann::json(value), node.file(), node.path()),
                   &scratch);
  } catch (const InputError& e) {
    node.Fail(
        fmt::format("with relative_step {}, derivatives are taken at {}, which breaks "
                    "{}'s rule: {}",
                    step, value, ParamName(spec), e.rule()));
  }
}

// Lab summaries as a calibration's targets or a comparison's quantities name
// them: quantity, part (of the scene's sequence, or "all"), by ("operator" or
// "all"), segment (1-based) and condition (the lab's, not empty: without it,
// any), and for a comparison the equivalence margin.
std::vector<FitTarget> ReadTargets(const JsonNode& list, const Scene& scene,
                                   bool margin) {
  std::vector<FitTarget> out;
  const std::size_t m = list.ArraySize(1);
  for (std::size_t k = 0; k < m; ++k) {
    const JsonNode node = list.At(k);
    if (margin) {
      node.ExpectObject({"quantity", "part", "by", "segment", "condition", "margin"});
    } else {
      node.ExpectObject({"quantity", "part", "by", "segment", "condition"});
    }
    FitTarget t;
    t.pointer = node.path();
    t.quantity = node.Required("quantity").Choice({"assembly_time", "success_rate"});
    std::vector<std::string> parts = {"all"};
    for (int index : scene.sequence) parts.push_back(scene.parts[index].name);
    t.part = node.Required("part").Choice(parts);
    if (auto by = node.Optional("by"))
      t.by_operator = by->Choice({"operator", "all"}) == "operator";
    if (auto segment = node.Optional("segment"))
      t.segment = static_cast<int>(segment->Integer(1, 1000));
    if (auto condition = node.Optional("condition")) {
      t.condition = condition->String();
      if (t.condition.empty())
        condition->Fail("names the lab's condition; leave the key out to read any");
    }
    if (t.segment > 0 && t.by_operator)
      node.Required("by").Fail("a segment's value is the lab's over all operators");
    // A margin is in the quantity's unit: at most an hour for a time, 1 for a rate.
    if (margin)
      t.margin =
          node.Required("margin").InRange(0, t.quantity == "assembly_time" ? 3600 : 1);
    if (margin && !(t.margin > 0)) node.Required("margin").Fail("must be > 0");
    out.push_back(t);
  }
  return out;
}

// A stage's parameters, targets and solver, from `node` (a stage of
// "stages", or the file's root for a file of one stage).
CalibrationStage ReadStage(const JsonNode& node, const CalibrationDesign& d,
                           const Scene& scene, const std::string& path) {
  CalibrationStage stage;
  if (auto solver = node.Optional("solver"))
    stage.solver = solver->Choice({"levenberg_marquardt", "golden_section"});
  const JsonNode params = node.Required("parameters");
  const std::size_t n = params.ArraySize(1);
  if (stage.solver == "golden_section" && n != 1)
    params.Fail(
        "the golden_section solver fits exactly one parameter; use levenberg_marquardt, "
        "or one "
        "stage per parameter");
  for (std::size_t k = 0; k < n; ++k) {
    const JsonNode p_node = params.At(k);
    p_node.ExpectObject({"name", "start", "lower", "upper"});
    FitParameter p;
    p.pointer = p_node.path();
    const JsonNode name = p_node.Required("name");
    p.name = name.Choice(ParamNames());
    const ParamSpec& spec = *FindParam(p.name);
    if (!spec.real) name.Fail("a calibration fits real-valued parameters");
    for (const CalibrationStage& earlier : d.stages)
      for (const FitParameter& other : earlier.parameters)
        if (other.name == p.name)
          name.Fail("fitted once only (also at " + other.pointer + ")");
    for (const FitParameter& other : stage.parameters)
      if (other.name == p.name)
        name.Fail("fitted once only (also at " + other.pointer + ")");
    const JsonNode lower = p_node.Required("lower"), upper = p_node.Required("upper"),
                   start = p_node.Required("start");
    p.lower = lower.Number();
    p.upper = upper.Number();
    p.start = start.Number();
    if (!(p.lower < p.upper)) upper.Fail(fmt::format("must exceed lower = {}", p.lower));
    if (!(p.lower <= p.start && p.start <= p.upper))
      start.Fail(
          fmt::format("must lie within [lower, upper] = [{}, {}]", p.lower, p.upper));
    // Numeric derivatives step a relative_step beyond the bounds.
    CheckFitValue(spec, lower, p.lower * (1 - d.relative_step), d.relative_step);
    CheckFitValue(spec, upper, p.upper * (1 + d.relative_step), d.relative_step);
    stage.parameters.push_back(p);
  }
  stage.targets = ReadTargets(node.Required("targets"), scene, false);
  // One virtual design per stage: the lab's operators, or the hour of work
  // in segments.
  for (const FitTarget& t : stage.targets)
    if ((t.segment > 0) != (stage.targets[0].segment > 0))
      throw InputError(
          path, t.pointer, t.quantity,
          "targets of segments and targets without a segment cannot be fitted "
          "in one stage (one runs the fatigue design, the other the lab's "
          "operators): put them in stages of their own");
  return stage;
}

// Segment targets or quantities lie within the fatigue design's hour.
void CheckSegments(const std::vector<FitTarget>& targets, const FatigueDesign& fatigue,
                   const std::string& path) {
  for (const FitTarget& t : targets)
    if (t.segment > fatigue.segments)
      throw InputError(
          path, t.pointer + "/segment", std::to_string(t.segment),
          fmt::format("the fatigue design has {} segments", fatigue.segments));
}

}  // namespace

void ReadCalibration(const JsonNode& root, const std::string& path, ExperimentFile* e) {
  ReadFatigue(root, path, e);
  CalibrationDesign& d = e->calibration;
  d.fatigue = e->fatigue;
  d.lab_path = ResolvePath(root.Required("lab"), path, "lab dataset");
  if (auto step = root.Optional("relative_step"))
    d.relative_step = step->InRange(1e-4, 0.5);
  if (auto it = root.Optional("max_iterations"))
    d.max_iterations = static_cast<int>(it->Integer(1, 1000));
  if (auto tol = root.Optional("tolerance")) d.tolerance = tol->InRange(1e-4, 0.5);
  if (auto loss = root.Optional("loss")) {
    loss->ExpectObject({"kind", "scale"});
    d.loss = loss->Required("kind").Choice({"huber", "cauchy", "none"});
    if (auto scale = loss->Optional("scale")) d.loss_scale = scale->InRange(0.1, 100);
  }
  if (auto stages = root.Optional("stages")) {
    for (const char* key : {"parameters", "targets", "solver"})
      if (auto node = root.Optional(key))
        node->Fail(
            "a calibration in stages states its parameters, targets and solver in "
            "each stage");
    const std::size_t n = stages->ArraySize(1);
    for (std::size_t k = 0; k < n; ++k) {
      const JsonNode node = stages->At(k);
      node.ExpectObject({"name", "solver", "parameters", "targets"});
      CalibrationStage stage = ReadStage(node, d, e->scene, path);
      stage.pointer = node.path();
      stage.name = node.Required("name").String();
      for (const CalibrationStage& earlier : d.stages)
        if (earlier.name == stage.name)
          node.Required("name").Fail("a stage name is used once (also " +
                                     earlier.pointer + ")");
      d.stages.push_back(std::move(stage));
    }
  } else {
    d.stages.push_back(ReadStage(root, d, e->scene, path));
  }
  for (const CalibrationStage& stage : d.stages)
    CheckSegments(stage.targets, d.fatigue, path);
}

void ReadComparison(const JsonNode& root, const std::string& path, ExperimentFile* e) {
  ReadFatigue(root, path, e);
  ComparisonDesign& d = e->comparison;
  d.lab_path = ResolvePath(root.Required("lab"), path, "lab dataset");
  d.quantities = ReadTargets(root.Required("quantities"), e->scene, true);
  d.fatigue = e->fatigue;
  CheckSegments(d.quantities, d.fatigue, path);
}

namespace {

// The value `pointer` (RFC 6901, parsed by nlohmann::json's json_pointer)
// names in `document`, or null when it names none; `why` says which token
// fails and why. "" (the whole document) names none: a patch changes a value
// inside the scene.
nlohmann::json* Resolve(nlohmann::json& document, const std::string& pointer,
                        std::string* why) {
  using Pointer = nlohmann::json::json_pointer;
  Pointer target;
  try {
    target = Pointer(pointer);
  } catch (const nlohmann::json::exception&) {
    target = Pointer();
  }
  if (target.empty()) {
    *why =
        "a JSON pointer into the scene starts with '/' and writes '~' as ~0 and '/' as "
        "~1 "
        "(RFC 6901), e.g. /parts/0/friction";
    return nullptr;
  }
  const auto holds = [&](const Pointer& p) {
    try {
      return document.contains(p);
    } catch (const nlohmann::json::exception&) {  // an array index beyond size_t
      return false;
    }
  };
  if (holds(target)) return &document.at(target);
  // What fails: the first token past the longest prefix the document holds.
  std::vector<std::string> tokens;
  for (Pointer p = target; !p.empty(); p.pop_back()) tokens.push_back(p.back());
  Pointer held;
  while (holds(held / tokens.back())) {
    held /= tokens.back();
    tokens.pop_back();
  }
  const nlohmann::json& at = document.at(held);
  const std::string where = held.empty() ? "the scene's root" : held.to_string();
  if (at.is_object())
    *why = fmt::format(
        "the scene has no '{}' at {}; a patch replaces a value the scene "
        "already holds",
        tokens.back(), where);
  else if (at.is_array())
    *why = fmt::format("{} holds {} elements; '{}' names none of them", where, at.size(),
                       tokens.back());
  else
    *why = fmt::format("{} is a {}, not an object or an array", where, at.type_name());
  return nullptr;
}

// Whether `where` (a scene pointer an error names) lies at or under `pointer`.
bool Under(const std::string& where, const std::string& pointer) {
  return where.compare(0, pointer.size(), pointer) == 0 &&
         (where.size() == pointer.size() || where[pointer.size()] == '/');
}

// The scene of a case, from its patched `document`: read by the scene loader,
// its parameters overridden; a scene rule it breaks names the experiment file
// and the case's pointer (the patch entry at fault, or the case).
Scene CaseScene(const StabilityCase& c, const JsonNode& node,
                const nlohmann::json& document) {
  const std::optional<JsonNode> patch = node.Optional("patch");
  Scene scene;
  try {
    scene = ParseScene(document, c.scene_path);
  } catch (const InputError& e) {
    for (const auto& [pointer, value] : c.patch)
      if (Under(e.where(), pointer))
        throw InputError(
            node.file(),
            patch->Required(pointer).path() + e.where().substr(pointer.size()), e.value(),
            e.rule() + " (scene " + c.scene_path + ", patched)");
    node.Fail(fmt::format("the scene {}{} breaks a rule: {}", c.scene_path,
                          c.patch.empty() ? "" : " with the case's patch", e.what()));
  }
  const std::optional<JsonNode> parameters = node.Optional("parameters");
  for (const auto& [name, value] : c.overrides)
    ReadParamValue(*FindParam(name), parameters->Required(name), &scene.params);
  if (c.position >= static_cast<int>(scene.sequence.size()))
    node.Required("position")
        .Fail(fmt::format("the scene's sequence has {} part(s): positions 0 to {}",
                          scene.sequence.size(), scene.sequence.size() - 1));
  return scene;
}

// The case's scene under one of its integrators.
Scene UnderIntegrator(const StabilityCase& c, const JsonNode& node, Scene scene,
                      const std::string& integrator) {
  const nlohmann::json integrator_value = integrator;
  ReadParamValue(*FindParam("simulation/integrator"),
                 JsonNode(integrator_value, node.file(), node.path() + "/integrators"),
                 &scene.params);
  const std::string violation = ParameterViolation(scene);
  if (!violation.empty())
    node.Fail("applied to scene '" + scene.name + "' (" + c.scene_path +
              "): " + violation);
  return scene;
}

std::vector<std::string> ReadIntegrators(const JsonNode& list) {
  std::vector<std::string> out;
  const std::size_t n = list.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string name = list.At(k).Choice(StepperNames());
    if (std::find(out.begin(), out.end(), name) != out.end())
      list.At(k).Fail("an integrator is listed once");
    out.push_back(name);
  }
  return out;
}

}  // namespace

void ReadStability(const JsonNode& root, const std::string& path, ExperimentFile* e) {
  StabilityDesign& d = e->stability;
  d.integrators = ReadIntegrators(root.Required("integrators"));
  const JsonNode cases = root.Required("cases");
  const std::size_t n = cases.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const JsonNode node = cases.At(k);
    node.ExpectObject({"name", "scene", "position", "parameters", "patch", "integrators",
                       "seeds", "expect"});
    StabilityCase c;
    c.pointer = node.path();
    c.name = node.Required("name").String();
    if (c.name.empty()) node.Required("name").Fail("a case needs a non-empty name");
    for (const StabilityCase& other : d.cases)
      if (other.name == c.name)
        node.Required("name").Fail("case names are unique (also " + other.pointer + ")");
    c.scene_path = ResolvePath(node.Required("scene"), path, "scene");
    if (auto position = node.Optional("position"))
      c.position = static_cast<int>(position->Integer(0, 1000));
    nlohmann::json document = ReadJsonFile(c.scene_path);  // read once, patched in place
    if (auto patch = node.Optional("patch")) {
      if (!patch->json().is_object())
        patch->Fail("a patch is an object of JSON pointer into the scene -> value");
      for (const auto& item : patch->json().items()) {  // in key order
        const JsonNode entry = patch->Required(item.key());
        for (const auto& [earlier, value] : c.patch)
          if (Under(item.key(), earlier))
            entry.Fail("lies inside " + earlier + ", which the same patch replaces");
        std::string why;
        nlohmann::json* at = Resolve(document, item.key(), &why);
        if (at == nullptr) entry.Fail(why);
        *at = item.value();
        c.patch.emplace_back(item.key(), item.value());
      }
    }
    if (auto parameters = node.Optional("parameters")) {
      parameters->ExpectObject(ParamNames());
      Parameters scratch;
      for (const auto& item : parameters->json().items()) {
        const JsonNode value = parameters->Required(item.key());
        if (item.key() == "simulation/integrator")
          value.Fail("a case names its integrators in \"integrators\"");
        ReadParamValue(*FindParam(item.key()), value, &scratch);
        c.overrides.emplace_back(item.key(), item.value());
      }
    }
    c.integrators = d.integrators;
    if (auto list = node.Optional("integrators")) c.integrators = ReadIntegrators(*list);
    if (auto seeds = node.Optional("seeds"))
      c.seeds = static_cast<int>(seeds->Integer(1, 1000));
    const JsonNode expect = node.Required("expect");
    const std::size_t m = expect.ArraySize(1);
    for (std::size_t j = 0; j < m; ++j) {
      const std::string name = expect.At(j).String();
      if (std::find(c.expect.begin(), c.expect.end(), name) != c.expect.end())
        expect.At(j).Fail("an outcome class is listed once");
      c.expect.push_back(name);
      c.expect_pointers.push_back(expect.At(j).path());
    }
    const Scene scene = CaseScene(c, node, document);
    for (const std::string& integrator : c.integrators)
      c.scenes.push_back(UnderIntegrator(c, node, scene, integrator));
    d.cases.push_back(std::move(c));
  }
  e->scene_path = d.cases[0].scene_path;
  e->scene = d.cases[0].scenes[0];
}

std::string DescribeStability(const ExperimentFile& e) {
  const StabilityDesign& d = e.stability;
  std::string out = fmt::format("stability: {} case(s); integrators by default: {}\n",
                                d.cases.size(), fmt::join(d.integrators, ", "));
  for (const StabilityCase& c : d.cases) {
    out += fmt::format("  {} ({}): {}, position {}, {} seed(s), expects {}\n", c.name,
                       c.pointer, c.scene_path, c.position, c.seeds,
                       fmt::join(c.expect, " or "));
    for (const auto& [pointer, value] : c.patch)
      out += fmt::format("    patch {} = {}\n", pointer, value.dump());
    for (const auto& [name, value] : c.overrides)
      out += fmt::format("    {} = {}\n", name, value.dump());
    out += fmt::format("    integrators: {}\n", fmt::join(c.integrators, ", "));
  }
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
  const PrecisionDesign& d = e.precision;
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

ExperimentFile ReadExperimentHeader(const JsonNode& root, const std::string& path,
                                    const std::vector<std::string>& kinds) {
  const JsonNode format = root.Required("format");
  if (format.String() != kExperimentFormat)
    format.Fail(std::string("an experiment file declares \"format\": \"") +
                kExperimentFormat + "\"");
  ExperimentFile e;
  e.file = path;
  e.name = root.Required("name").String();
  if (auto d = root.Optional("description")) e.description = d->String();
  e.kind = root.Required("kind").Choice(kinds);
  if (auto seed = root.Optional("seed")) e.seed = seed->Unsigned();
  if (auto trials = root.Optional("trials"))
    e.trials = static_cast<int>(trials->Integer(1, 10'000'000));
  return e;
}

void ReadExperimentScene(const JsonNode& root, const std::string& path,
                         ExperimentFile* e) {
  e->scene_path = ResolvePath(root.Required("scene"), path, "scene");
  e->scene = LoadScene(e->scene_path);
}

void ReadTable1(const JsonNode& root, const std::string& path, ExperimentFile* e) {
  if (auto t = root.Optional("paper_table"))
    e->paper_table_path = ResolvePath(*t, path, "paper table");
}

void ReadAssemblyTime(const JsonNode& root, const std::string&, ExperimentFile* e) {
  if (auto ops = root.Optional("operators")) e->operators = ReadOperators(*ops, e->scene);
}

void ReadHumanFactorsGroups(const JsonNode& root, const std::string& path,
                            ExperimentFile* e) {
  const JsonNode list = root.Required("conditions");
  const std::size_t n = list.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const JsonNode c = list.At(k);
    c.ExpectObject({"name", "scene"});
    ConditionEntry entry;
    entry.name = c.Required("name").String();
    entry.scene_path = ResolvePath(c.Required("scene"), path, "scene");
    entry.scene = LoadScene(entry.scene_path);
    for (const ConditionEntry& other : e->conditions)
      if (other.name == entry.name)
        c.Required("name").Fail("condition names must be unique");
    e->conditions.push_back(std::move(entry));
  }
  if (auto cycle = root.Optional("paper_cycle_s")) e->paper_cycle_s = cycle->Positive();
  const JsonNode instants = root.Required("instants_s");
  const std::size_t m = instants.ArraySize(1);
  for (std::size_t k = 0; k < m; ++k) {
    const double t = instants.At(k).Positive();
    if (t > e->paper_cycle_s)
      instants.At(k).Fail(
          fmt::format("an instant lies within the paper's cycle, paper_cycle_s = {} s",
                      e->paper_cycle_s));
    e->instants_s.push_back(t);
  }
}

void ReadFatigue(const JsonNode& root, const std::string&, ExperimentFile* e) {
  const auto f = root.Optional("fatigue");
  if (!f) return;
  f->ExpectObject({"duration_min", "segments", "pilot_cycles"});
  if (auto d = f->Optional("duration_min")) e->fatigue.duration_min = d->Positive();
  if (auto s = f->Optional("segments"))
    e->fatigue.segments = static_cast<int>(s->Integer(1, 1000));
  if (auto p = f->Optional("pilot_cycles"))
    e->fatigue.pilot_cycles = static_cast<int>(p->Integer(0, 10'000'000));
}

std::string FileFormatOf(const std::string& path) {
  return FormatOf(ReadJsonFile(path), path);
}

std::string FormatOf(const nlohmann::json& document, const std::string& path) {
  const JsonNode root(document, path);
  if (!document.is_object()) root.Fail("a vahf file is a JSON object");
  const JsonNode format = root.Required("format");
  const std::string f = format.String();
  if (f == kSceneFormat) return "scene";
  if (f == kExperimentFormat) return "experiment";
  if (f == kLabFormat) return "lab";
  if (f == kOverridesFormat) return "overrides";
  if (f == kSyntheticFormat) return "synthetic";
  format.Fail(fmt::format("must be one of \"{}\", \"{}\", \"{}\", \"{}\", \"{}\"",
                          kSceneFormat, kExperimentFormat, kLabFormat, kOverridesFormat,
                          kSyntheticFormat));
}

}  // namespace vahf::scene
