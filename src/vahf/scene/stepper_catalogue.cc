#include "vahf/scene/stepper_catalogue.h"

namespace vahf::scene {

const std::vector<StepperInfo>& StepperCatalogue() {
#define VAHF_STEPPER(name, needs, factory, description) \
  {name, description, StepperNeeds::needs},
  static const std::vector<StepperInfo> catalogue = {
#include "vahf/scene/steppers.def"
  };
#undef VAHF_STEPPER
  return catalogue;
}

std::vector<std::string> StepperNames() {
  std::vector<std::string> names;
  for (const StepperInfo& s : StepperCatalogue()) names.emplace_back(s.name);
  return names;
}

}  // namespace vahf::scene
