#include "vahf/scene/experiment_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene_loader.h"

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
