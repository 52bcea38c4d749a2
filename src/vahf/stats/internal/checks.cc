#include "vahf/stats/internal/checks.h"

#include <fmt/format.h>

#include <cmath>

#include "vahf/core/error.h"

namespace vahf::stats::internal {

void RequireFinite(const std::vector<double>& xs, const char* function,
                   const char* name) {
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (!std::isfinite(xs[i])) {
      throw ComputationError(
          ComputationError::Reason::kOutOfDomain,
          fmt::format("{}: {}[{}] = {}: must be finite", function, name, i, xs[i]));
    }
  }
}

void RequireSize(const std::vector<double>& xs, std::size_t at_least,
                 const char* function, const char* name) {
  if (xs.size() < at_least) {
    throw ComputationError(ComputationError::Reason::kTooFewValues,
                           fmt::format("{}: {} has {} values: needs at least {}",
                                       function, name, xs.size(), at_least));
  }
}

void RequireLevel(double level, const char* function) {
  if (!(level > 0 && level < 1)) {
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("{}: level = {}: must lie in (0, 1)", function, level));
  }
}

}  // namespace vahf::stats::internal
