#include "vahf/core/piecewise_linear.h"

#include <algorithm>
#include <cmath>

#include "vahf/core/error.h"

namespace vahf {

std::string PiecewiseLinear::Violation(const std::vector<Knot>& knots) {
  if (knots.empty()) return "a curve needs at least one knot";
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i].x) || !std::isfinite(knots[i].y))
      return "knot " + std::to_string(i) + " is not finite";
    if (i > 0 && !(knots[i].x > knots[i - 1].x))
      return "knot x values must increase strictly (knot " + std::to_string(i) + ")";
  }
  return {};
}

PiecewiseLinear::PiecewiseLinear(std::vector<Knot> knots) : knots_(std::move(knots)) {
  const std::string violation = Violation(knots_);
  VAHF_CHECK(violation.empty(), violation);
}

double PiecewiseLinear::operator()(double x) const {
  if (x <= knots_.front().x) return knots_.front().y;
  if (x >= knots_.back().x) return knots_.back().y;
  const auto hi = std::upper_bound(knots_.begin(), knots_.end(), x,
                                   [](double v, const Knot& k) { return v < k.x; });
  const auto lo = hi - 1;
  const double s = (x - lo->x) / (hi->x - lo->x);
  return lo->y + s * (hi->y - lo->y);
}

}  // namespace vahf
