#include "vahf/experiment/fatigue_input.h"

#include <memory>

namespace vahf::experiment {

void ReadFatigueExperiment(const scene::JsonNode& root, const std::string&,
                           scene::ExperimentFile* e) {
  auto input = std::make_unique<FatigueInput>();
  input->fatigue = scene::ReadFatigue(root);
  e->input = core::ClonePtr<scene::KindInput>(std::move(input));
}

}  // namespace vahf::experiment
