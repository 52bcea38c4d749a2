// The Simbody integrators a trial may use, by name (scene parameter
// simulation/integrator, or `vahf trial --integrator`).
#pragma once

#include <memory>
#include <string>

namespace SimTK {
class Integrator;
class System;
}  // namespace SimTK

namespace vahf::sim {

// RungeKuttaMerson, RungeKutta3, RungeKuttaFeldberg (explicit, error
// controlled); CPodes (BDF with Newton iteration: for stiff contact); Verlet,
// SemiExplicitEuler2 (error controlled, for second-order systems); FixedStep
// (Runge-Kutta-Merson with error control off, step `fixed_step`). `accuracy`
// is the relative accuracy of the error-controlled ones.
std::unique_ptr<SimTK::Integrator> MakeIntegrator(const std::string& name,
                                                  const SimTK::System& system,
                                                  double accuracy, double fixed_step);

}  // namespace vahf::sim
