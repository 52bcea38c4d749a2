// The paper kind (docs/experiments.md, "paper"): the experiments it lists
// (paper_input.h), each validated before the first trial of any, run into one
// output directory.
#include <fmt/format.h>

#include <set>
#include <string>

#include "vahf/kinds/kind.h"
#include "vahf/kinds/paper_input.h"
#include "vahf/report/handbook_section.h"

namespace vahf::kinds {
namespace {

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

// The handbooks section, when the file names the tables.
std::vector<report::Section> PaperSections(const experiment::ExperimentRun& run) {
  const PaperInput& in = run.file->Input<PaperInput>();
  if (!in.handbooks) return {};
  const experiment::ExperimentRun* times = nullptr;
  for (const experiment::ExperimentRun& part : run.parts)
    if (!times && FindKind(part.file->kind).times_the_parts) times = &part;
  return {report::HandbookSection(times, in.handbooks->boothroyd_dewhurst,
                                  in.handbooks->mtm1_position)};
}

std::vector<const scene::ExperimentFile*> PaperParts(const scene::ExperimentFile& file) {
  std::vector<const scene::ExperimentFile*> out;
  for (const scene::ExperimentFile& x : file.Input<PaperInput>().experiments)
    out.push_back(&x);
  return out;
}

}  // namespace

Kind PaperKind() {
  Kind k;
  k.name = "paper";
  k.summary = "the paper's experiments, one report";
  k.doc = "experiments.md";
  k.keys = {"experiments", "handbooks"};
  k.scene_elsewhere = "a paper experiment takes its scenes from the experiments it lists";
  k.parse = ParsePaper;
  k.check = CheckPaper;
  k.design = PaperRun;
  k.sections_after_parts = PaperSections;
  k.parts = PaperParts;
  k.cycles_per_condition = false;  // each listed experiment has its own
  return k;
}

}  // namespace vahf::kinds
