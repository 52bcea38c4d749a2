#include "vahf/stats/proportion.h"

#include <fmt/format.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vahf/core/error.h"
#include "vahf/stats/internal/checks.h"

namespace vahf::stats {
namespace {

void RequireCount(Count c, const char* function, const char* name) {
  if (c.trials < 1 || c.successes < 0 || c.successes > c.trials) {
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("{}: {} = {} of {}: needs trials >= 1 and 0 <= successes <= trials",
                    function, name, c.successes, c.trials));
  }
}

}  // namespace

Interval WilsonInterval(Count c, double level) {
  internal::RequireLevel(level, "WilsonInterval");
  RequireCount(c, "WilsonInterval", "count");
  const double n = static_cast<double>(c.trials);
  const double p = static_cast<double>(c.successes) / n;
  const double z = gsl_cdf_ugaussian_Pinv(0.5 * (1.0 + level));
  const double z2n = z * z / n;
  const double center = (p + 0.5 * z2n) / (1.0 + z2n);
  const double half = z / (1.0 + z2n) * std::sqrt(p * (1.0 - p) / n + 0.25 * z2n / n);
  // At k = 0 (k = n) the lower (upper) end is 0 (1) in exact arithmetic;
  // rounding must not move it off.
  Interval out{std::max(0.0, center - half), std::min(1.0, center + half)};
  if (c.successes == 0) out.lower = 0.0;
  if (c.successes == c.trials) out.upper = 1.0;
  return out;
}

double FisherRateFellP(Count before, Count after) {
  RequireCount(before, "FisherRateFellP", "before");
  RequireCount(after, "FisherRateFellP", "after");
  constexpr auto kMax = std::numeric_limits<unsigned int>::max();  // GSL's argument type
  if (before.trials + after.trials > static_cast<std::int64_t>(kMax)) {
    throw ComputationError(ComputationError::Reason::kOutOfDomain,
                           "FisherRateFellP: more trials than GSL can count");
  }
  // Of all trials (urn), `successes` are white; `after` draws after.trials.
  const auto successes = static_cast<unsigned int>(before.successes + after.successes);
  const auto failures =
      static_cast<unsigned int>(before.trials + after.trials) - successes;
  return gsl_cdf_hypergeometric_P(static_cast<unsigned int>(after.successes), successes,
                                  failures, static_cast<unsigned int>(after.trials));
}

}  // namespace vahf::stats
