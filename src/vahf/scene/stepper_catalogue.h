// The steppers a scene may name (parameter simulation/integrator), as the scene
// layer sees them: the list of steppers.def without its factories, which live in
// sim (sim/stepper_registry.h), above this layer.
#pragma once

#include <string>
#include <vector>

namespace vahf::scene {

// What a stepper steps: a Simbody system (the Simbody driver, sim/trial.cc, steps
// the stepper's SimTK::Integrator) or the trial model's own right-hand side (the
// stepper is its own driver).
enum class StepperNeeds { kSimbodySystem, kOwnRightHandSide };

struct StepperInfo {
  const char* name;
  const char* description;  // one line, for vahf params
  StepperNeeds needs;
};

// Every stepper, in the order of steppers.def.
const std::vector<StepperInfo>& StepperCatalogue();
std::vector<std::string> StepperNames();

}  // namespace vahf::scene
