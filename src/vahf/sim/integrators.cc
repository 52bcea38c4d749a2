#include "vahf/sim/internal/integrators.h"

#include <Simbody.h>

#include <utility>

#include "vahf/scene/stepper_catalogue.h"

namespace vahf::sim::internal {
namespace {

// A trial steps from one decision instant to the next; let the integrator take
// as many internal steps as stiff contact needs in between (CPodes' own
// default of 500 prints errors and retries).
std::unique_ptr<SimTK::Integrator> Limited(std::unique_ptr<SimTK::Integrator> integ) {
  integ->setInternalStepLimit(1000000);
  return integ;
}

std::unique_ptr<SimTK::Integrator> ErrorControlled(
    std::unique_ptr<SimTK::Integrator> integ, const scene::SimulationParams& settings) {
  integ = Limited(std::move(integ));
  integ->setAccuracy(settings.accuracy);
  return integ;
}

}  // namespace

std::unique_ptr<SimTK::Integrator> MakeRungeKuttaMerson(
    const SimTK::System& system, const scene::SimulationParams& settings) {
  return ErrorControlled(std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system),
                         settings);
}

std::unique_ptr<SimTK::Integrator> MakeRungeKutta3(
    const SimTK::System& system, const scene::SimulationParams& settings) {
  return ErrorControlled(std::make_unique<SimTK::RungeKutta3Integrator>(system),
                         settings);
}

std::unique_ptr<SimTK::Integrator> MakeRungeKuttaFeldberg(
    const SimTK::System& system, const scene::SimulationParams& settings) {
  return ErrorControlled(std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(system),
                         settings);
}

std::unique_ptr<SimTK::Integrator> MakeCPodes(const SimTK::System& system,
                                              const scene::SimulationParams& settings) {
  return ErrorControlled(std::make_unique<SimTK::CPodesIntegrator>(
                             system, SimTK::CPodes::BDF, SimTK::CPodes::Newton),
                         settings);
}

std::unique_ptr<SimTK::Integrator> MakeVerlet(const SimTK::System& system,
                                              const scene::SimulationParams& settings) {
  return ErrorControlled(std::make_unique<SimTK::VerletIntegrator>(system), settings);
}

std::unique_ptr<SimTK::Integrator> MakeSemiExplicitEuler2(
    const SimTK::System& system, const scene::SimulationParams& settings) {
  return ErrorControlled(std::make_unique<SimTK::SemiExplicitEuler2Integrator>(system),
                         settings);
}

std::unique_ptr<SimTK::Integrator> MakeFixedStep(
    const SimTK::System& system, const scene::SimulationParams& settings) {
  auto integ = Limited(std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system));
  integ->setFixedStepSize(
      settings.stepper_values.Get(scene::stepper_settings::fixed_step));
  return integ;
}

}  // namespace vahf::sim::internal
