// The checks of the designs of cycles (experiment/design.h) and the paper run,
// which runs the experiments it lists into one output directory.
#include <fmt/format.h>

#include <set>
#include <string>

#include "vahf/experiment/groups_input.h"
#include "vahf/experiment/precision_design.h"
#include "vahf/kinds/kind_functions.h"
#include "vahf/kinds/paper_input.h"
#include "vahf/kinds/run_support.h"
#include "vahf/scene/json_reader.h"
#include "vahf/sim/trial_model.h"

namespace vahf::kinds {

std::string CheckOneScene(const scene::ExperimentFile& file) {
  return DescribeSceneModels(file.scene);
}

std::string CheckGroups(const scene::ExperimentFile& file) {
  std::string out;
  for (const experiment::ConditionEntry& c :
       file.Input<experiment::GroupsInput>().conditions)
    out += fmt::format("condition '{}' ({}):\n", c.name, c.scene_path) +
           DescribeSceneModels(c.scene);
  return out;
}

// The settings, and the trial models of every scene under every setting (what
// only building can reject, a setting's shell spacing say, fails now).
std::string CheckPrecision(const scene::ExperimentFile& file) {
  std::string out = experiment::DescribePrecision(file);
  for (const experiment::PrecisionScene& s :
       file.Input<experiment::PrecisionDesign>().scenes) {
    out += DescribeSceneModels(s.reference);
    for (const scene::Scene& setting : s.settings) sim::BuildSequenceModels(setting);
  }
  return out;
}

std::string CheckPaper(const scene::ExperimentFile& file) {
  std::string out;
  std::set<std::string> checked;  // a file listed again is the same experiment
  for (const scene::ExperimentFile& x : file.Input<PaperInput>().experiments) {
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
  for (const scene::ExperimentFile& x : file.Input<PaperInput>().experiments)
    out.parts.push_back(RunDesign(x, settings));
  return out;
}

}  // namespace vahf::kinds
