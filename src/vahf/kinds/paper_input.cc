#include "vahf/kinds/paper_input.h"

#include <fmt/format.h>

#include <memory>
#include <utility>

#include "vahf/kinds/kind.h"
#include "vahf/scene/overrides.h"

namespace vahf::kinds {

void PaperInput::ApplyOverrides(const scene::ParameterOverrides& o,
                                scene::ExperimentFile*) {
  for (scene::ExperimentFile& sub : experiments) scene::ApplyOverrides(o, &sub);
}

std::vector<std::string> PaperInput::InputFiles() const {
  if (!handbooks) return {};
  return {handbooks->boothroyd_dewhurst.file, handbooks->mtm1_position.file};
}

namespace {

// "handbooks": the two tables, each file relative to the experiment file.
PaperInput::Handbooks ReadHandbooks(const scene::JsonNode& node,
                                    const std::string& path) {
  node.ExpectObject({"boothroyd_dewhurst", "mtm1_position"});
  PaperInput::Handbooks out;
  out.boothroyd_dewhurst = data::ReadBdInsertion(scene::ResolvePath(
      node.Required("boothroyd_dewhurst"), path, "Boothroyd-Dewhurst insertion table"));
  out.mtm1_position = data::ReadMtmPosition(
      scene::ResolvePath(node.Required("mtm1_position"), path, "MTM-1 Position table"));
  return out;
}

// "table1, assembly_time, ...": the kinds a paper run may list, the designs of
// cycles with an analysis of their own (the paper run itself has none).
std::string DesignNames() {
  std::string out;
  for (const Kind& k : Kinds())
    if (k.design && k.analyse) out += (out.empty() ? "" : ", ") + k.name;
  return out;
}

}  // namespace

void ParsePaper(const scene::JsonNode& root, const std::string& path,
                scene::ExperimentFile* e) {
  auto input = std::make_unique<PaperInput>();
  const scene::JsonNode list = root.Required("experiments");
  const std::size_t n = list.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string sub = scene::ResolvePath(list.At(k), path, "experiment");
    // Checked before parsing, so a file listing itself cannot recurse: a
    // listed file of this kind (the registry's name, e->kind) is refused.
    const nlohmann::json doc = scene::ReadJsonFile(sub);
    if (doc.is_object() && doc.contains("kind") && doc["kind"] == e->kind)
      list.At(k).Fail("a paper experiment cannot list another paper experiment");
    scene::ExperimentFile x = ParseExperiment(doc, sub);
    if (!FindKind(x.kind).design)
      list.At(k).Fail(fmt::format(
          "{} is a {} experiment: a paper run lists designs of cycles ({}); run it on "
          "its own",
          sub, x.kind, DesignNames()));
    input->experiments.push_back(std::move(x));
  }
  if (const auto h = root.Optional("handbooks"))
    input->handbooks = ReadHandbooks(*h, path);
  e->input = core::ClonePtr<scene::KindInput>(std::move(input));
}

}  // namespace vahf::kinds
