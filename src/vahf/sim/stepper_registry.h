// The steppers' registry (docs/design.md decision 13): each stepper's name,
// description, what it needs and its factory. A Simbody stepper's factory makes
// its SimTK::Integrator and the Simbody driver (trial.cc) steps it; a stepper of
// the trial model's own right-hand side is a core (stepper_core.h) the shared
// driver steps (internal/stepper_driver.h; CVODE's: internal/cvode_stepper.h).
//
// One list, scene/steppers.def, holds the entries and the steppers' own
// settings: the scene layer reads it for the parameter table's choices and rows
// (scene/stepper_catalogue.h), and this layer, above scene, reads it again with
// the factories, declaring each with its kind's type. So the names are written
// once, no scene file includes sim, and no stepper needs a header for the
// registry. A new stepper is its lines in scene/steppers.def and its factory
// in its own .cc, listed in src/CMakeLists.txt (integrators.cc for a Simbody
// integrator; docs/extending.md, "A stepper", for a core).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "vahf/scene/parameters.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/stepper_core.h"
#include "vahf/sim/trial_result.h"

namespace SimTK {
class Integrator;
class System;
}  // namespace SimTK

namespace vahf::sim {

// Makes the SimTK::Integrator that the Simbody driver steps, set from the
// scene's simulation parameters (internal/integrators.h).
using IntegratorFactory = std::unique_ptr<SimTK::Integrator> (*)(
    const SimTK::System& system, const scene::SimulationParams& settings);
// A core's factory (CoreFactory, stepper_core.h) for the shared driver.

struct StepperEntry {
  const char* name;
  const char* description;  // one line, for vahf params
  scene::StepperNeeds needs;
  IntegratorFactory make_integrator = nullptr;  // kSimbodySystem
  CoreFactory make_core = nullptr;              // kOwnRightHandSide, kContactPoints
};

// Every stepper, in the order of scene/steppers.def.
const std::vector<StepperEntry>& Steppers();

// The stepper `name` (one of scene::StepperNames: the parameter table checked it).
const StepperEntry& FindStepper(const std::string& name);

}  // namespace vahf::sim
