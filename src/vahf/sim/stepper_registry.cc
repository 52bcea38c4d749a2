#include "vahf/sim/stepper_registry.h"

#include "vahf/core/error.h"
#include "vahf/sim/internal/cvode_stepper.h"
#include "vahf/sim/internal/integrators.h"

namespace vahf::sim {
namespace {

using namespace internal;  // the factories
using scene::StepperNeeds;

// An entry of scene/steppers.def with its factory, which must be the kind its
// needs name: a mismatch does not compile.
template <StepperNeeds needs>
StepperEntry Entry(const char* name, const char* description, IntegratorFactory factory) {
  static_assert(needs == StepperNeeds::kSimbodySystem,
                "an integrator factory makes what the Simbody driver steps");
  return {name, description, needs, factory, nullptr};
}

template <StepperNeeds needs>
StepperEntry Entry(const char* name, const char* description, Driver factory) {
  static_assert(needs == StepperNeeds::kOwnRightHandSide,
                "a driver steps the trial model's own right-hand side");
  return {name, description, needs, nullptr, factory};
}

}  // namespace

const std::vector<StepperEntry>& Steppers() {
#define VAHF_STEPPER(name, needs, factory, description) \
  Entry<StepperNeeds::needs>(name, description, factory),
  static const std::vector<StepperEntry> steppers = {
#include "vahf/scene/steppers.def"
  };
#undef VAHF_STEPPER
  return steppers;
}

const StepperEntry& FindStepper(const std::string& name) {
  for (const StepperEntry& s : Steppers())
    if (name == s.name) return s;
  VAHF_CHECK(false, "unknown integrator " + name + " passed validation");
  return Steppers().front();
}

}  // namespace vahf::sim
