// The experiment kinds: one entry each (kind.h), defined in the kind's own
// file and listed once in kinds.def. docs/kinds.md indexes them (`vahf kinds`);
// docs/scene-format.md, "Experiment files", gives the common keys.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "vahf/core/error.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/manifest.h"
#include "vahf/report/run_output.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/overrides.h"

namespace vahf::kinds {

#define VAHF_KIND(F) Kind F();
#include "vahf/kinds/kinds.def"
#undef VAHF_KIND

const std::vector<Kind>& Kinds() {
  static const std::vector<Kind> kinds = {
#define VAHF_KIND(F) F(),
#include "vahf/kinds/kinds.def"
#undef VAHF_KIND
  };
  return kinds;
}

std::vector<std::string> KindNames() {
  std::vector<std::string> names;
  for (const Kind& k : Kinds()) names.push_back(k.name);
  return names;
}

const Kind& FindKind(const std::string& name) {
  for (const Kind& k : Kinds())
    if (k.name == name) return k;
  VAHF_CHECK(false, "an experiment kind that was not registered: " + name);
  return Kinds().front();
}

namespace {

// "\"fatigue\", \"calibrate\" or \"compare\"": the kinds that read `key`.
std::string KindsReading(const std::string& key) {
  std::vector<std::string> names;
  for (const Kind& k : Kinds())
    if (std::find(k.keys.begin(), k.keys.end(), key) != k.keys.end())
      names.push_back("\"" + k.name + "\"");
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
}

}  // namespace

scene::ExperimentFile LoadExperiment(const std::string& path) {
  return ParseExperiment(scene::ReadJsonFile(path), path);
}

scene::ExperimentFile LoadExperiment(const std::string& path,
                                     const std::string& overrides) {
  scene::ExperimentFile file = LoadExperiment(path);
  if (!overrides.empty()) scene::ApplyOverrides(scene::LoadOverrides(overrides), &file);
  return file;
}

std::string DefaultRunDirectory(const scene::ExperimentFile& file, std::uint64_t seed) {
  return "runs/" + file.name + "-seed" + std::to_string(seed);
}

scene::ExperimentFile ParseExperiment(const nlohmann::json& document,
                                      const std::string& path) {
  const scene::JsonNode root(document, path);
  std::vector<std::string> keys = {"format", "name", "description", "kind",
                                   "scene",  "seed", "trials"};
  for (const Kind& k : Kinds())
    for (const std::string& key : k.keys)
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  root.ExpectObject(keys);
  scene::ExperimentFile e = scene::ReadExperimentHeader(root, path, KindNames());
  const Kind& kind = FindKind(e.kind);
  // A key that only another kind reads is a mistake worth naming.
  for (auto it = document.begin(); it != document.end(); ++it) {
    const std::string& key = it.key();
    const std::string readers = KindsReading(key);
    if (!readers.empty() &&
        std::find(kind.keys.begin(), kind.keys.end(), key) == kind.keys.end())
      root.Required(key).Fail("only an experiment of kind " + readers + " reads \"" +
                              key + "\"");
  }
  if (kind.scene_elsewhere.empty())
    scene::ReadExperimentScene(root, path, &e);
  else if (auto scene = root.Optional("scene"))
    scene->Fail(kind.scene_elsewhere);
  kind.parse(root, path, &e);
  return e;
}

std::string CheckExperiment(const scene::ExperimentFile& file) {
  std::string out =
      fmt::format("experiment '{}' ({}): kind {}, seed {}{}\n", file.name, file.file,
                  file.kind, file.seed,
                  FindKind(file.kind).cycles_per_condition
                      ? fmt::format(", {} cycles per condition", file.trials)
                      : "");
  return out + FindKind(file.kind).check(file);
}

experiment::ExperimentRun RunDesign(const scene::ExperimentFile& file,
                                    const experiment::RunSettings& settings) {
  const Kind& kind = FindKind(file.kind);
  VAHF_CHECK(kind.design != nullptr, "RunDesign of a kind that is no design of cycles");
  return kind.design(file, settings);
}

std::vector<report::Section> Sections(const experiment::ExperimentRun& run) {
  std::vector<report::Section> out;
  const auto add = [&](const experiment::ExperimentRun& r) {
    const Kind& kind = FindKind(r.file->kind);
    out.push_back(report::SectionFor(kind.name, r, kind.analyse(r)));
  };
  if (run.parts.empty()) add(run);
  for (const experiment::ExperimentRun& part : run.parts) add(part);
  if (!run.parts.empty())
    if (const auto after = FindKind(run.file->kind).sections_after_parts)
      for (report::Section& s : after(run)) out.push_back(std::move(s));
  return out;
}

int RunExperiment(const scene::ExperimentFile& file, const RunContext& given) {
  const Kind& kind = FindKind(file.kind);
  kind.check(file);  // what check rejects fails now, before any trial
  RunContext context = given;
  context.kind = &kind;
  // The journal: what it takes to resume this run (docs/reproducibility.md).
  std::vector<std::string> files = {file.file, file.overrides_path, file.scene_path};
  if (file.input)
    for (const std::string& f : file.input->InputFiles()) files.push_back(f);
  const auto open = [&] {
    context.settings.journal = &context.directory->OpenJournal(report::RunIdentity(
        {file.file, file.overrides_path, context.settings.seed, context.settings.trials},
        files));
  };
  // Rank 0's refusal (a journal of another run) stops every rank alike.
  experiment::AllAgree(context.settings.ranks, open);
  // A --resume with nothing journaled yet starts afresh, and says so.
  if (const std::string& why = context.directory->afresh_reason(); !why.empty())
    std::fprintf(stderr,
                 "vahf: %s: nothing journaled to resume (%s): the run starts afresh\n",
                 context.directory->path().c_str(), why.c_str());
  if (kind.run) return kind.run(file, context);
  const auto start = std::chrono::steady_clock::now();
  const experiment::ExperimentRun run = RunDesign(file, context.settings);
  const report::RunInfo info = RunInfoOf(context.settings, start);
  const report::RunOutput written =
      report::WriteRunOutput(run, Sections(run), *context.directory, info);
  return FinishRun(file, context, info.wall_seconds, written);
}

}  // namespace vahf::kinds
