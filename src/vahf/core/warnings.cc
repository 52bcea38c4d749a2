#include "vahf/core/warnings.h"

#include <fmt/format.h>

namespace vahf {

const char* WarningName(WarningKind kind) {
  switch (kind) {
    case WarningKind::kNonFiniteState:
      return "non_finite_state";
    case WarningKind::kPenetrationBound:
      return "penetration_bound";
    case WarningKind::kStepSizeFloor:
      return "step_size_floor";
    case WarningKind::kIntegratorRetry:
      return "integrator_retry";
    case WarningKind::kIntegratorFailure:
      return "integrator_failure";
    case WarningKind::kContactSolver:
      return "contact_solver";
    case WarningKind::kRest:
      return "rest";
  }
  return "?";
}

void Warnings::Add(const Warnings& other) {
  for (int k = 0; k < kWarningKinds; ++k) {
    const WarningEntry& o = other.entries_[k];
    if (o.count == 0) continue;
    WarningEntry& e = entries_[k];
    if (e.count == 0) {
      e.first_time = o.first_time;
      e.detail = o.detail;
    }
    e.count += o.count;
  }
}

std::int64_t Warnings::total() const {
  std::int64_t n = 0;
  for (const WarningEntry& e : entries_) n += e.count;
  return n;
}

std::string Warnings::Summary() const {
  std::string out;
  for (int k = 0; k < kWarningKinds; ++k) {
    const WarningEntry& e = entries_[k];
    if (e.count == 0) continue;
    if (!out.empty()) out += "; ";
    out += fmt::format("{} {} (first at t = {:.6g} s: {})",
                       WarningName(static_cast<WarningKind>(k)), e.count, e.first_time,
                       e.detail);
  }
  return out.empty() ? "none" : out;
}

}  // namespace vahf
