#include "vahf/compare/comparison_input.h"

#include <memory>
#include <utility>

#include "vahf/data/lab_dataset.h"

namespace vahf::compare {

std::vector<std::string> ComparisonDesign::InputFiles() const {
  return data::LabDatasetFiles(data::LoadLabDataset(lab_path));
}

void ReadComparison(const scene::JsonNode& root, const std::string& path,
                    scene::ExperimentFile* e) {
  ComparisonDesign d;
  d.fatigue = scene::ReadFatigue(root);
  d.lab_path = scene::ResolvePath(root.Required("lab"), path, "lab dataset");
  d.quantities = scene::ReadTargets(root.Required("quantities"), e->scene, true);
  scene::CheckSegments(d.quantities, d.fatigue, path);
  e->input =
      core::ClonePtr<scene::KindInput>(std::make_unique<ComparisonDesign>(std::move(d)));
}

}  // namespace vahf::compare
