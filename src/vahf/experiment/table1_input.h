// The input of a table1 experiment (docs/experiments.md, "table1"): the
// paper's Table 1 to show beside the virtual values, if any.
#pragma once

#include <string>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"

namespace vahf::experiment {

struct Table1Input : scene::KindInputOf<Table1Input> {
  // The paper's Table 1 as JSON (reference/paper/table1.json); empty: no
  // comparison.
  std::string paper_table_path;

  std::vector<std::string> InputFiles() const override;  // the paper table
};

// table1: "paper_table".
void ReadTable1(const scene::JsonNode& root, const std::string& path,
                scene::ExperimentFile* e);

}  // namespace vahf::experiment
