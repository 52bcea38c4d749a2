#include "vahf/experiment/stability_input.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "vahf/core/error.h"
#include "vahf/scene/overrides.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/scene/stepper_catalogue.h"

namespace vahf::experiment {

using scene::ExperimentFile;
using scene::FindParam;
using scene::JsonNode;
using scene::Parameters;
using scene::ParameterViolation;
using scene::ParamNames;
using scene::ParseScene;
using scene::ReadJsonFile;
using scene::ReadParamValue;
using scene::ResolvePath;
using scene::Scene;
using scene::StepperNames;

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
  StabilityDesign d;
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
  e->input =
      core::ClonePtr<scene::KindInput>(std::make_unique<StabilityDesign>(std::move(d)));
}

std::string DescribeStability(const ExperimentFile& e) {
  const StabilityDesign& d = e.Input<StabilityDesign>();
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

void StabilityDesign::ApplyOverrides(const scene::ParameterOverrides& o,
                                     scene::ExperimentFile* file) {
  // A case runs each of its integrators.
  for (StabilityCase& c : cases)
    for (scene::Scene& scene : c.scenes)
      scene::ApplyOverridesExcept(o, c.overrides, "simulation/integrator", &scene);
  if (!cases.empty()) file->scene = cases[0].scenes[0];
}

}  // namespace vahf::experiment
