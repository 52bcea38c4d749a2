#include "vahf/sim/stepper_registry.h"

#include <type_traits>

#include "vahf/core/error.h"

namespace vahf::sim {

using scene::StepperNeeds;

namespace internal {

// The function type of a factory of each kind.
template <StepperNeeds needs>
struct FactoryOf;
template <>
struct FactoryOf<StepperNeeds::kSimbodySystem> {
  using Type = std::remove_pointer_t<IntegratorFactory>;
};
template <>
struct FactoryOf<StepperNeeds::kOwnRightHandSide> {
  using Type = std::remove_pointer_t<CoreFactory>;
};
template <>
struct FactoryOf<StepperNeeds::kContactPoints> {
  using Type = std::remove_pointer_t<CoreFactory>;
};

// Every factory scene/steppers.def names, declared with the type its needs
// name, so no stepper has a header for this file to include. A factory
// defined with the other kind's signature is another function: the build
// fails at link time, naming the declared one it does not find.
#define VAHF_STEPPER(name, needs, factory, description) \
  FactoryOf<StepperNeeds::needs>::Type factory;
#define VAHF_STEPPER_SETTING(key, unit, rule, lo, hi, default_value, meaning)
#include "vahf/scene/steppers.def"
#undef VAHF_STEPPER
#undef VAHF_STEPPER_SETTING

}  // namespace internal

namespace {

using namespace internal;  // the factories

// An entry of scene/steppers.def with its factory, whose type the declarations
// above took from the line's needs.
StepperEntry Entry(const char* name, const char* description, StepperNeeds,
                   IntegratorFactory factory) {
  return {name, description, StepperNeeds::kSimbodySystem, factory, nullptr};
}

StepperEntry Entry(const char* name, const char* description, StepperNeeds needs,
                   CoreFactory factory) {
  return {name, description, needs, nullptr, factory};
}

}  // namespace

const std::vector<StepperEntry>& Steppers() {
#define VAHF_STEPPER(name, needs, factory, description) \
  Entry(name, description, StepperNeeds::needs, factory),
#define VAHF_STEPPER_SETTING(key, unit, rule, lo, hi, default_value, meaning)
  static const std::vector<StepperEntry> steppers = {
#include "vahf/scene/steppers.def"
  };
#undef VAHF_STEPPER
#undef VAHF_STEPPER_SETTING
  return steppers;
}

const StepperEntry& FindStepper(const std::string& name) {
  for (const StepperEntry& s : Steppers())
    if (name == s.name) return s;
  VAHF_CHECK(false, "unknown integrator " + name + " passed validation");
  return Steppers().front();
}

}  // namespace vahf::sim
