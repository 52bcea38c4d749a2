// Simbody's integrators, one factory each (their entries in scene/steppers.def):
// the SimTK::Integrator the Simbody driver (trial.cc) steps between decisions,
// set from the scene's simulation parameters; each is an IntegratorFactory
// (stepper_registry.h).
#pragma once

#include <memory>

#include "vahf/scene/parameters.h"

namespace SimTK {
class Integrator;
class System;
}  // namespace SimTK

namespace vahf::sim::internal {

// Explicit and error controlled at relative accuracy settings.accuracy.
std::unique_ptr<SimTK::Integrator> MakeRungeKuttaMerson(
    const SimTK::System& system, const scene::SimulationParams& settings);
std::unique_ptr<SimTK::Integrator> MakeRungeKutta3(
    const SimTK::System& system, const scene::SimulationParams& settings);
std::unique_ptr<SimTK::Integrator> MakeRungeKuttaFeldberg(
    const SimTK::System& system, const scene::SimulationParams& settings);
// BDF with Newton iteration (for stiff contact), at settings.accuracy.
std::unique_ptr<SimTK::Integrator> MakeCPodes(const SimTK::System& system,
                                              const scene::SimulationParams& settings);
// Error controlled, for second-order systems, at settings.accuracy.
std::unique_ptr<SimTK::Integrator> MakeVerlet(const SimTK::System& system,
                                              const scene::SimulationParams& settings);
std::unique_ptr<SimTK::Integrator> MakeSemiExplicitEuler2(
    const SimTK::System& system, const scene::SimulationParams& settings);
// Runge-Kutta-Merson with error control off, step simulation/fixed_step.
std::unique_ptr<SimTK::Integrator> MakeFixedStep(const SimTK::System& system,
                                                 const scene::SimulationParams& settings);

}  // namespace vahf::sim::internal
