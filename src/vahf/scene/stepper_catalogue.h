// The steppers a scene may name (parameter simulation/integrator), as the scene
// layer sees them: the list of steppers.def without its factories, which live in
// sim (sim/stepper_registry.h), above this layer.
#pragma once

#include <string>
#include <vector>

#include "vahf/core/param_decl.h"

namespace vahf::scene {

// What a stepper steps: a Simbody system (the Simbody driver, sim/trial.cc, steps
// the stepper's SimTK::Integrator), the trial model's own right-hand side (a
// core the shared driver steps), or, a core too, the contact model's exact
// contact points (contact::ContactModel::AddContactPoints: a nonsmooth
// stepper; a scene whose contact model has none is refused).
enum class StepperNeeds { kSimbodySystem, kOwnRightHandSide, kContactPoints };

struct StepperInfo {
  const char* name;
  const char* description;  // one line, for vahf params
  StepperNeeds needs;
};

// Every stepper, in the order of steppers.def.
const std::vector<StepperInfo>& StepperCatalogue();
std::vector<std::string> StepperNames();

// The steppers' own settings, one declaration each (steppers.def's
// VAHF_STEPPER_SETTING lines): code reads stepper_settings::max_order from
// SimulationParams::stepper_values.
namespace stepper_settings {
#define VAHF_STEPPER(name, needs, factory, description)
#define VAHF_STEPPER_SETTING(key, unit, rule, lo, hi, default_value, meaning) \
  inline constexpr core::ParamDecl key{                                       \
      #key, unit, core::ParamRule::rule, lo, hi, default_value, meaning};
#include "vahf/scene/steppers.def"
#undef VAHF_STEPPER
#undef VAHF_STEPPER_SETTING
}  // namespace stepper_settings

// Every stepper setting, in the order of steppers.def.
const std::vector<const core::ParamDecl*>& StepperSettings();

}  // namespace vahf::scene
