// What a statistics function refuses with: the reason and message of the
// vahf::ComputationError it throws. A test that compares both fails when a
// check is removed (nothing thrown) and when a case is refused for the wrong
// reason (a zero variance taken for too few values).
#pragma once

#include <string>

#include "vahf/core/error.h"

namespace vahf::stats {

struct Refusal {
  std::string reason;  // "too few values", "zero variance", "out of domain", "refused"
  std::string message;
};

inline std::string ReasonName(ComputationError::Reason r) {
  switch (r) {
    case ComputationError::Reason::kTooFewValues:
      return "too few values";
    case ComputationError::Reason::kZeroVariance:
      return "zero variance";
    case ComputationError::Reason::kOutOfDomain:
      return "out of domain";
    case ComputationError::Reason::kRefused:
      return "refused";
  }
  return "(unknown reason)";
}

// Calls f; its refusal, or reason "(not refused)" when it returned.
template <class F>
Refusal RefusalOf(F&& f) {
  try {
    f();
  } catch (const ComputationError& e) {
    return {ReasonName(e.reason()), e.what()};
  }
  return {"(not refused)", ""};
}

}  // namespace vahf::stats
