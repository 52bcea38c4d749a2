#include "vahf/sim/stepper_core.h"

#include <fmt/format.h>

#include "vahf/sim/internal/trial_context.h"

namespace vahf::sim {

bool RightHandSide::Derivative(const BodyState& y, BodyState* dydt) {
  const contact::RigidMotion m = MotionOf(y);
  if (!internal::IsFinite(m)) return false;
  const Loads loads = c_.LoadsAt(m, held_);
  *dydt = sim::Derivative(c_.model, y, loads, c_.model.gravity);
  return true;
}

const TrialModel& RightHandSide::model() const { return c_.model; }

const scene::SimulationParams& RightHandSide::settings() const {
  return c_.params().simulation;
}

std::string StepperCore::RetryDetail(std::int64_t retries) const {
  return fmt::format("{} integrator retries", retries);
}

}  // namespace vahf::sim
