#include "vahf/scene/experiment_file.h"

#include <filesystem>

#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::scene {

const std::vector<std::string>& ExperimentKinds() {
  static const std::vector<std::string> kinds = {
      "table1",  "assembly_time", "human_factors_groups", "fatigue", "compare",
      "calibrate", "precision",   "stability"};
  return kinds;
}

ExperimentFile LoadExperiment(const std::string& path) {
  return ParseExperiment(ReadJsonFile(path), path);
}

ExperimentFile ParseExperiment(const nlohmann::json& document, const std::string& path) {
  const JsonNode root(document, path);
  root.ExpectObject({"format", "name", "description", "kind", "scene", "seed", "trials"});
  const JsonNode format = root.Required("format");
  if (format.String() != kExperimentFormat)
    format.Fail(std::string("an experiment file declares \"format\": \"") +
                kExperimentFormat + "\"");
  ExperimentFile e;
  e.file = path;
  e.name = root.Required("name").String();
  e.kind = root.Required("kind").Choice(ExperimentKinds());
  const JsonNode scene = root.Required("scene");
  const std::filesystem::path relative = scene.String();
  e.scene_path = relative.is_absolute()
                     ? relative.string()
                     : (std::filesystem::path(path).parent_path() / relative).string();
  if (!std::filesystem::is_regular_file(e.scene_path))
    scene.Fail("no scene file at " + e.scene_path +
               " (a relative path is taken from the experiment file's folder)");
  if (auto seed = root.Optional("seed")) e.seed = seed->Unsigned();
  if (auto trials = root.Optional("trials"))
    e.trials = static_cast<int>(trials->Integer(1, 10'000'000));
  e.scene = LoadScene(e.scene_path);
  return e;
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
  format.Fail(std::string("must be \"") + kSceneFormat + "\" or \"" + kExperimentFormat +
              "\"");
}

}  // namespace vahf::scene
