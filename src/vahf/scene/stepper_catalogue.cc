#include "vahf/scene/stepper_catalogue.h"

namespace vahf::scene {

const std::vector<StepperInfo>& StepperCatalogue() {
#define VAHF_STEPPER(name, needs, factory, description) \
  {name, description, StepperNeeds::needs},
#define VAHF_STEPPER_SETTING(key, unit, rule, lo, hi, default_value, meaning)
  static const std::vector<StepperInfo> catalogue = {
#include "vahf/scene/steppers.def"
  };
#undef VAHF_STEPPER
#undef VAHF_STEPPER_SETTING
  return catalogue;
}

std::vector<std::string> StepperNames() {
  std::vector<std::string> names;
  for (const StepperInfo& s : StepperCatalogue()) names.emplace_back(s.name);
  return names;
}

const std::vector<const core::ParamDecl*>& StepperSettings() {
#define VAHF_STEPPER(name, needs, factory, description)
#define VAHF_STEPPER_SETTING(key, unit, rule, lo, hi, default_value, meaning) \
  &stepper_settings::key,
  static const std::vector<const core::ParamDecl*> settings = {
#include "vahf/scene/steppers.def"
  };
#undef VAHF_STEPPER
#undef VAHF_STEPPER_SETTING
  return settings;
}

}  // namespace vahf::scene
