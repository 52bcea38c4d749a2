// The checks of the designs of cycles (experiment/design.h) and the paper run,
// which runs the experiments it lists into one output directory.
#include <fmt/format.h>

#include <set>
#include <string>

#include "vahf/kinds/kind_functions.h"
#include "vahf/kinds/run_support.h"
#include "vahf/scene/json_reader.h"
#include "vahf/sim/trial_model.h"

namespace vahf::kinds {

std::string CheckOneScene(const scene::ExperimentFile& file) {
  return DescribeSceneModels(file.scene);
}

std::string CheckGroups(const scene::ExperimentFile& file) {
  std::string out;
  for (const scene::ConditionEntry& c : file.conditions)
    out += fmt::format("condition '{}' ({}):\n", c.name, c.scene_path) +
           DescribeSceneModels(c.scene);
  return out;
}

// The settings, and the trial models of every scene under every setting (what
// only building can reject, a setting's shell spacing say, fails now).
std::string CheckPrecision(const scene::ExperimentFile& file) {
  std::string out = scene::DescribePrecision(file);
  for (const scene::PrecisionScene& s : file.precision.scenes) {
    out += DescribeSceneModels(s.reference);
    for (const scene::Scene& setting : s.settings) sim::BuildSequenceModels(setting);
  }
  return out;
}

// The experiments a paper run lists, each from its own file and a design of
// cycles (their outputs share one directory); they name their scenes.
void ParsePaper(const scene::JsonNode& root, const std::string& path,
                scene::ExperimentFile* e) {
  const scene::JsonNode list = root.Required("experiments");
  const std::size_t n = list.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string sub = scene::ResolvePath(list.At(k), path, "experiment");
    // Checked before parsing, so a file listing itself cannot recurse.
    const nlohmann::json doc = scene::ReadJsonFile(sub);
    if (doc.is_object() && doc.contains("kind") && doc["kind"] == "paper")
      list.At(k).Fail("a paper experiment cannot list another paper experiment");
    scene::ExperimentFile x = ParseExperiment(doc, sub);
    if (!FindKind(x.kind).design)
      list.At(k).Fail(
          fmt::format("{} is a {} experiment: a paper run lists designs of cycles "
                      "(table1, assembly_time, human_factors_groups, fatigue, "
                      "precision); run it on its own",
                      sub, x.kind));
    e->experiments.push_back(std::move(x));
  }
}

std::string CheckPaper(const scene::ExperimentFile& file) {
  std::string out;
  std::set<std::string> checked;  // a file listed again is the same experiment
  for (const scene::ExperimentFile& x : file.experiments) {
    // Every experiment valid before the first trial of any; each file once.
    if (checked.insert(x.file).second) FindKind(x.kind).check(x);
    out += fmt::format("  {} ({}): kind {}, {} cycles per condition, scene {}: valid\n",
                       x.name, x.file, x.kind, x.trials, x.scene_path);
  }
  return out;
}

experiment::ExperimentRun PaperRun(const scene::ExperimentFile& file,
                                   const experiment::RunSettings& settings) {
  experiment::ExperimentRun out;
  out.file = &file;
  out.seed = settings.seed;
  out.trials = settings.trials;  // 0: each experiment its own
  for (const scene::ExperimentFile& x : file.experiments)
    out.parts.push_back(RunDesign(x, settings));
  return out;
}

}  // namespace vahf::kinds
