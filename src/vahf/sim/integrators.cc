#include "vahf/sim/integrators.h"

#include <Simbody.h>

#include "vahf/core/error.h"

namespace vahf::sim {

std::unique_ptr<SimTK::Integrator> MakeIntegrator(const std::string& name,
                                                  const SimTK::System& system,
                                                  double accuracy, double fixed_step) {
  std::unique_ptr<SimTK::Integrator> integ;
  if (name == "RungeKuttaMerson" || name == "FixedStep")
    integ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
  else if (name == "RungeKutta3")
    integ = std::make_unique<SimTK::RungeKutta3Integrator>(system);
  else if (name == "RungeKuttaFeldberg")
    integ = std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(system);
  else if (name == "CPodes")
    integ = std::make_unique<SimTK::CPodesIntegrator>(system, SimTK::CPodes::BDF,
                                                      SimTK::CPodes::Newton);
  else if (name == "Verlet")
    integ = std::make_unique<SimTK::VerletIntegrator>(system);
  else if (name == "SemiExplicitEuler2")
    integ = std::make_unique<SimTK::SemiExplicitEuler2Integrator>(system);
  VAHF_CHECK(integ != nullptr, "unknown integrator " + name + " passed validation");
  // A trial steps from one decision instant to the next; let the integrator take
  // as many internal steps as stiff contact needs in between (CPodes' own
  // default of 500 prints errors and retries).
  integ->setInternalStepLimit(1000000);
  if (name == "FixedStep")
    integ->setFixedStepSize(fixed_step);
  else
    integ->setAccuracy(accuracy);
  return integ;
}

}  // namespace vahf::sim
