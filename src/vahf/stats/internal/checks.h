// Argument checks shared by the statistics functions: each throws
// vahf::ComputationError (too few values: kTooFewValues; else kOutOfDomain)
// whose message names the function, the argument, the value and the rule,
// e.g. "Mean: xs[3] = nan: must be finite".
#pragma once

#include <cstddef>
#include <vector>

namespace vahf::stats::internal {

void RequireFinite(const std::vector<double>& xs, const char* function,
                   const char* name = "xs");
void RequireSize(const std::vector<double>& xs, std::size_t at_least,
                 const char* function, const char* name = "xs");
// A confidence level in the open interval (0, 1).
void RequireLevel(double level, const char* function);

}  // namespace vahf::stats::internal
