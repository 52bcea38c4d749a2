// docs/kinds.md: the registry's kinds as one Markdown page (`vahf kinds`).
#include <fmt/format.h>

#include <string>

#include "vahf/kinds/kind.h"

namespace vahf::kinds {

std::string KindIndexMarkdown() {
  std::string out =
      "# Experiment kinds\n\n"
      "Every kind an experiment file may name in \"kind\", in the registry's order\n"
      "(src/vahf/kinds/kinds.def; each kind's entry is in its own kinds/*_kind.cc).\n"
      "Written by `vahf kinds`; tests/kinds/registry_test.cc checks that this file is\n"
      "its current output (regenerate with `vahf kinds > docs/kinds.md`). Keys are\n"
      "those a kind reads besides the common ones (format, name, description, kind,\n"
      "scene, seed, trials; docs/scene-format.md, \"Experiment files\").\n\n"
      "| kind | what it runs and shows | its keys | its scenes | described in |\n"
      "| --- | --- | --- | --- | --- |\n";
  for (const Kind& k : Kinds()) {
    std::string keys;
    for (const std::string& key : k.keys)
      keys += (keys.empty() ? "`" : ", `") + key + "`";
    const std::string file = k.doc.substr(0, k.doc.find('#'));
    out += fmt::format("| `{}` | {} | {} | {} | [{}]({}) |\n", k.name, k.summary, keys,
                       k.scene_elsewhere.empty() ? "\"scene\"" : k.scene_elsewhere, file,
                       k.doc);
  }
  return out;
}

}  // namespace vahf::kinds
