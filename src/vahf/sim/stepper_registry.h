// The steppers' registry (docs/design.md decision 13): each stepper's name,
// description, what it needs and its factory. A Simbody stepper's factory makes
// its SimTK::Integrator and the Simbody driver (trial.cc) steps it; a stepper of
// the trial model's own right-hand side is its own driver (CVODE's:
// internal/cvode_stepper.h).
//
// One list, scene/steppers.def, holds the entries: the scene layer reads it for
// the parameter table's choices (scene/stepper_catalogue.h), and this layer, above
// scene, reads it again with the factories. So the names are written once and no
// scene file includes sim. A new stepper is its line in scene/steppers.def and its
// factory in its own files: integrators.cc and internal/integrators.h for a
// Simbody integrator; for one of its own, its .cc and a header in internal/, the
// .cc in src/CMakeLists.txt, and the header included by stepper_registry.cc.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vahf/scene/parameters.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/trial_result.h"

namespace SimTK {
class Integrator;
class System;
}  // namespace SimTK

namespace vahf::sim {
namespace internal {
struct TrialContext;
}  // namespace internal

// Makes the SimTK::Integrator that the Simbody driver steps, set from the
// scene's simulation parameters (internal/integrators.h).
using IntegratorFactory = std::unique_ptr<SimTK::Integrator> (*)(
    const SimTK::System& system, const scene::SimulationParams& settings);

// Makes the decision at t = 0 and steps the trial to its end: the time reached;
// sets *final_row and the counters (internal/cvode_stepper.h's contract).
using Driver = double (*)(internal::TrialContext& c, double sample_interval,
                          std::optional<TraceRow>* final_row, TrialCounters* counters);

struct StepperEntry {
  const char* name;
  const char* description;  // one line, for vahf params
  scene::StepperNeeds needs;
  IntegratorFactory make_integrator = nullptr;  // kSimbodySystem
  Driver integrate = nullptr;                   // kOwnRightHandSide
};

// Every stepper, in the order of scene/steppers.def.
const std::vector<StepperEntry>& Steppers();

// The stepper `name` (one of scene::StepperNames: the parameter table checked it).
const StepperEntry& FindStepper(const std::string& name);

}  // namespace vahf::sim
