#include "vahf/scene/overrides.h"

#include <algorithm>

#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::scene {
namespace {

void Set(const ParameterOverrides& o, const std::string& name,
         const nlohmann::json& value, Scene* scene) {
  // Each value was read by its rule at load; reading it again cannot fail.
  ReadParamValue(*FindParam(name), JsonNode(value, o.file, "/parameters/" + name),
                 &scene->params);
}

void Check(const ParameterOverrides& o, const Scene& scene) {
  const std::string violation = ParameterViolation(scene);
  if (!violation.empty())
    throw InputError(o.file, "/parameters", "applied to scene '" + scene.name + "'",
                     violation);
}

}  // namespace

ParameterOverrides LoadOverrides(const std::string& path) {
  const nlohmann::json document = ReadJsonFile(path);
  const JsonNode root(document, path);
  if (!document.is_object()) root.Fail("an override file is a JSON object");
  root.ExpectObject({"format", "source", "parameters"});
  const JsonNode format = root.Required("format");
  if (format.String() != kOverridesFormat)
    format.Fail(std::string("an override file declares \"format\": \"") +
                kOverridesFormat + "\"");
  ParameterOverrides out;
  out.file = path;
  if (auto source = root.Optional("source")) out.source = source->String();
  const JsonNode params = root.Required("parameters");
  params.ExpectObject(ParamNames());
  Parameters scratch;
  for (const auto& item : params.json().items()) {
    ReadParamValue(*FindParam(item.key()), params.Required(item.key()), &scratch);
    out.values.emplace_back(item.key(), item.value());
  }
  if (out.values.empty()) params.Fail("names at least one parameter");
  return out;
}

void ApplyOverrides(const ParameterOverrides& o, Scene* scene) {
  for (const auto& [name, value] : o.values) Set(o, name, value, scene);
  Check(o, *scene);
}

void ApplyOverridesExcept(const ParameterOverrides& o,
                          const std::vector<std::pair<std::string, nlohmann::json>>& own,
                          const std::string& also_own, Scene* scene) {
  for (const auto& [name, value] : o.values) {
    const std::string& named = name;  // a lambda cannot capture a binding (C++17)
    const bool kept =
        named == also_own || std::any_of(own.begin(), own.end(),
                                         [&](const auto& s) { return s.first == named; });
    if (!kept) Set(o, name, value, scene);
  }
  Check(o, *scene);
}

void ApplyOverrides(const ParameterOverrides& o, ExperimentFile* file) {
  file->overrides_path = o.file;
  if (!file->scene_path.empty()) {
    const std::vector<std::string> own =
        file->input ? file->input->OwnParameters() : std::vector<std::string>{};
    for (const auto& [name, value] : o.values)
      if (std::find(own.begin(), own.end(), name) == own.end())
        Set(o, name, value, &file->scene);
    Check(o, file->scene);
  }
  if (file->input) file->input->ApplyOverrides(o, file);
}

}  // namespace vahf::scene
