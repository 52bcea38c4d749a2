#include "vahf/experiment/table1_input.h"

#include <memory>

namespace vahf::experiment {

std::vector<std::string> Table1Input::InputFiles() const {
  if (paper_table_path.empty()) return {};
  return {paper_table_path};
}

void ReadTable1(const scene::JsonNode& root, const std::string& path,
                scene::ExperimentFile* e) {
  auto input = std::make_unique<Table1Input>();
  if (auto t = root.Optional("paper_table"))
    input->paper_table_path = scene::ResolvePath(*t, path, "paper table");
  e->input = core::ClonePtr<scene::KindInput>(std::move(input));
}

}  // namespace vahf::experiment
