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

namespace {

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
  e->input = core::ClonePtr<scene::KindInput>(std::move(input));
}

}  // namespace vahf::kinds
