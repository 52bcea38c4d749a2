#include "vahf/stats/distribution.h"

#include <fmt/format.h>
#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vahf/core/error.h"
#include "vahf/stats/internal/checks.h"

namespace vahf::stats {

double Quantile(const std::vector<double>& xs, double p) {
  internal::RequireFinite(xs, "Quantile");
  internal::RequireSize(xs, 1, "Quantile");
  if (!(p >= 0 && p <= 1))
    throw ComputationError(ComputationError::Reason::kOutOfDomain,
                           fmt::format("Quantile: p = {}: must lie in [0, 1]", p));
  std::vector<double> sorted = xs;
  std::sort(sorted.begin(), sorted.end());
  return gsl_stats_quantile_from_sorted_data(sorted.data(), 1, sorted.size(), p);
}

KolmogorovSmirnov KolmogorovSmirnovTest(const std::vector<double>& a,
                                        const std::vector<double>& b) {
  for (const auto& [xs, name] : {std::pair{&a, "a"}, std::pair{&b, "b"}}) {
    internal::RequireFinite(*xs, "KolmogorovSmirnovTest", name);
    internal::RequireSize(*xs, 1, "KolmogorovSmirnovTest", name);
  }
  std::vector<double> x = a, y = b;
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  const double nx = static_cast<double>(x.size()), ny = static_cast<double>(y.size());
  // Walk the pooled values in order; after all copies of a value are passed
  // in both samples, i / nx and j / ny are the two empirical CDFs there.
  std::size_t i = 0, j = 0;
  double d = 0;
  while (i < x.size() && j < y.size()) {
    const double v = std::min(x[i], y[j]);
    while (i < x.size() && x[i] == v) ++i;
    while (j < y.size() && y[j] == v) ++j;
    d = std::max(d, std::fabs(static_cast<double>(i) / nx - static_cast<double>(j) / ny));
  }
  KolmogorovSmirnov r;
  r.distance = d;  // past the end of one sample the gap only shrinks to 0
  r.effective_n = nx * ny / (nx + ny);
  const double root = std::sqrt(r.effective_n);
  r.p_value = KolmogorovQ((root + 0.12 + 0.11 / root) * d);
  return r;
}

double KolmogorovQ(double lambda) {
  if (!(lambda >= 0) || !std::isfinite(lambda))
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("KolmogorovQ: lambda = {}: must be finite and >= 0", lambda));
  if (lambda == 0) return 1.0;
  double sum = 0;
  if (lambda < 1.18) {
    const double y = -M_PI * M_PI / (8 * lambda * lambda);
    for (int j = 1; j <= 100; ++j) {
      const double term = std::exp(y * (2 * j - 1) * (2 * j - 1));
      sum += term;
      if (term < 1e-17 * sum) break;
    }
    return std::clamp(1.0 - std::sqrt(2 * M_PI) / lambda * sum, 0.0, 1.0);
  }
  double sign = 1;
  for (int j = 1; j <= 100; ++j) {
    const double term = std::exp(-2.0 * j * j * lambda * lambda);
    sum += sign * term;
    sign = -sign;
    if (term < 1e-17) break;
  }
  return std::clamp(2 * sum, 0.0, 1.0);
}

double KsDistanceOfShift(const std::vector<double>& xs, double delta) {
  internal::RequireFinite(xs, "KsDistanceOfShift");
  internal::RequireSize(xs, 1, "KsDistanceOfShift");
  if (!(delta >= 0) || !std::isfinite(delta))
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("KsDistanceOfShift: delta = {}: must be finite and >= 0", delta));
  std::vector<double> s = xs;
  std::sort(s.begin(), s.end());
  // The most order statistics i..j with s[j] - s[i] < delta (a window
  // (x - delta, x] ending at s[j] holds them), by two pointers.
  std::size_t most = 0;
  for (std::size_t i = 0, j = 0; j < s.size(); ++j) {
    while (!(s[j] - s[i] < delta) && i < j) ++i;
    if (s[j] - s[i] < delta) most = std::max(most, j - i + 1);
  }
  return static_cast<double>(most) / static_cast<double>(s.size());
}

double KsEquivalentShift(const std::vector<double>& xs, double distance) {
  internal::RequireFinite(xs, "KsEquivalentShift");
  internal::RequireSize(xs, 1, "KsEquivalentShift");
  if (!(distance >= 0 && distance <= 1))
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("KsEquivalentShift: distance = {}: must lie in [0, 1]", distance));
  std::vector<double> s = xs;
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  // k = ceil(n D), with room for the rounding of a distance i/n - j/n.
  const auto k =
      static_cast<std::size_t>(std::ceil(distance * static_cast<double>(n) - 1e-9));
  if (k <= 1) return 0.0;
  double shift = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + k <= n; ++i) shift = std::min(shift, s[i + k - 1] - s[i]);
  return shift;
}

}  // namespace vahf::stats
