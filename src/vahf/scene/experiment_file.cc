#include "vahf/scene/experiment_file.h"

#include <fmt/format.h>

#include <filesystem>

#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::scene {

const std::vector<std::string>& ExperimentKinds() {
  static const std::vector<std::string> kinds = {
      "table1",  "assembly_time", "human_factors_groups", "fatigue", "paper",
      "compare", "calibrate",     "precision",            "stability"};
  return kinds;
}

ExperimentFile LoadExperiment(const std::string& path) {
  return ParseExperiment(ReadJsonFile(path), path);
}

namespace {

// A file named in `node`, relative to the experiment file's folder; it must exist.
std::string ResolvePath(const JsonNode& node, const std::string& experiment_path,
                        const char* what) {
  const std::filesystem::path relative = node.String();
  const std::string resolved =
      relative.is_absolute()
          ? relative.string()
          : (std::filesystem::path(experiment_path).parent_path() / relative).string();
  if (!std::filesystem::is_regular_file(resolved))
    node.Fail(std::string("no ") + what + " file at " + resolved +
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

}  // namespace

ExperimentFile ParseExperiment(const nlohmann::json& document, const std::string& path) {
  const JsonNode root(document, path);
  root.ExpectObject({"format", "name", "description", "kind", "scene", "seed", "trials",
                     "operators", "conditions", "instants_s", "paper_cycle_s", "fatigue",
                     "experiments", "paper_table"});
  const JsonNode format = root.Required("format");
  if (format.String() != kExperimentFormat)
    format.Fail(std::string("an experiment file declares \"format\": \"") +
                kExperimentFormat + "\"");
  ExperimentFile e;
  e.file = path;
  e.name = root.Required("name").String();
  if (auto d = root.Optional("description")) e.description = d->String();
  e.kind = root.Required("kind").Choice(ExperimentKinds());
  if (auto seed = root.Optional("seed")) e.seed = seed->Unsigned();
  if (auto trials = root.Optional("trials"))
    e.trials = static_cast<int>(trials->Integer(1, 10'000'000));
  // A key that only another kind reads is a mistake worth naming.
  const auto only_for = [&](const char* key, const char* kind) {
    if (auto node = root.Optional(key); node && e.kind != kind)
      node->Fail(std::string("only an experiment of kind \"") + kind + "\" reads \"" +
                 key + "\"");
  };
  only_for("operators", "assembly_time");
  only_for("conditions", "human_factors_groups");
  only_for("instants_s", "human_factors_groups");
  only_for("paper_cycle_s", "human_factors_groups");
  only_for("fatigue", "fatigue");
  only_for("experiments", "paper");
  only_for("paper_table", "table1");
  if (auto t = root.Optional("paper_table"))
    e.paper_table_path = ResolvePath(*t, path, "paper table");

  if (e.kind == "paper") {
    // The paper's experiments, each from its own file; they name their scenes.
    if (auto scene = root.Optional("scene"))
      scene->Fail("a paper experiment takes its scenes from the experiments it lists");
    const JsonNode list = root.Required("experiments");
    const std::size_t n = list.ArraySize(1);
    for (std::size_t k = 0; k < n; ++k) {
      const std::string sub = ResolvePath(list.At(k), path, "experiment");
      // Checked before parsing, so a file listing itself cannot recurse.
      const nlohmann::json doc = ReadJsonFile(sub);
      if (doc.is_object() && doc.contains("kind") && doc["kind"] == "paper")
        list.At(k).Fail("a paper experiment cannot list another paper experiment");
      e.experiments.push_back(ParseExperiment(doc, sub));
    }
    return e;
  }

  e.scene_path = ResolvePath(root.Required("scene"), path, "scene");
  e.scene = LoadScene(e.scene_path);
  if (auto ops = root.Optional("operators")) e.operators = ReadOperators(*ops, e.scene);
  if (e.kind == "human_factors_groups") {
    const JsonNode list = root.Required("conditions");
    const std::size_t n = list.ArraySize(1);
    for (std::size_t k = 0; k < n; ++k) {
      const JsonNode c = list.At(k);
      c.ExpectObject({"name", "scene"});
      ConditionEntry entry;
      entry.name = c.Required("name").String();
      entry.scene_path = ResolvePath(c.Required("scene"), path, "scene");
      entry.scene = LoadScene(entry.scene_path);
      for (const ConditionEntry& other : e.conditions)
        if (other.name == entry.name)
          c.Required("name").Fail("condition names must be unique");
      e.conditions.push_back(std::move(entry));
    }
    if (auto cycle = root.Optional("paper_cycle_s")) e.paper_cycle_s = cycle->Positive();
    const JsonNode instants = root.Required("instants_s");
    const std::size_t m = instants.ArraySize(1);
    for (std::size_t k = 0; k < m; ++k) {
      const double t = instants.At(k).Positive();
      if (t > e.paper_cycle_s)
        instants.At(k).Fail(fmt::format(
            "an instant lies within the paper's cycle, paper_cycle_s = {} s",
            e.paper_cycle_s));
      e.instants_s.push_back(t);
    }
  }
  if (auto f = root.Optional("fatigue")) {
    f->ExpectObject({"duration_min", "segments", "pilot_cycles"});
    if (auto d = f->Optional("duration_min")) e.fatigue.duration_min = d->Positive();
    if (auto s = f->Optional("segments"))
      e.fatigue.segments = static_cast<int>(s->Integer(1, 1000));
    if (auto p = f->Optional("pilot_cycles"))
      e.fatigue.pilot_cycles = static_cast<int>(p->Integer(0, 10'000'000));
  }
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
