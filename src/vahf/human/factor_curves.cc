#include "vahf/human/factor_curves.h"

#include <fmt/format.h>

#include "vahf/core/error.h"

namespace vahf::human {

std::string PlateauCurve::Violation() const {
  if (!(value_at_0 >= 0.0 && value_at_0 <= 1.0))
    return fmt::format("value_at_0 = {} must lie in [0, 1]", value_at_0);
  if (!(value_at_180 >= 0.0 && value_at_180 <= 1.0))
    return fmt::format("value_at_180 = {} must lie in [0, 1]", value_at_180);
  if (!(0.0 < plateau_from_deg && plateau_from_deg < plateau_to_deg &&
        plateau_to_deg < 180.0))
    return fmt::format(
        "the plateau must satisfy 0 < plateau_from_deg ({}) < plateau_to_deg ({}) < 180",
        plateau_from_deg, plateau_to_deg);
  return {};
}

PiecewiseLinear PlateauCurve::Build() const {
  VAHF_CHECK(Violation().empty(), Violation());
  return PiecewiseLinear({{0.0, value_at_0},
                          {plateau_from_deg, 1.0},
                          {plateau_to_deg, 1.0},
                          {180.0, value_at_180}});
}

ReachCurve::Breakpoints ReachCurve::BreakpointsFor(double arm_length,
                                                   double height) const {
  return {d1_arm_fraction * arm_length, d2_height_fraction * height,
          d3_height_fraction * height};
}

std::string ReachCurve::Violation(double arm_length, double height) const {
  if (!(value_at_d2 >= 0.0 && value_at_d2 <= 1.0))
    return fmt::format("value_at_d2 = {} must lie in [0, 1]", value_at_d2);
  const Breakpoints d = BreakpointsFor(arm_length, height);
  if (!(0.0 < d.d1 && d.d1 < d.d2 && d.d2 < d.d3))
    return fmt::format(
        "reach breakpoints must increase for this operator: D1 = {} * arm_length {} m "
        "= {:.4g} m, D2 = {} * height {} m = {:.4g} m, D3 = {} * height = {:.4g} m; "
        "need 0 < D1 < D2 < D3",
        d1_arm_fraction, arm_length, d.d1, d2_height_fraction, height, d.d2,
        d3_height_fraction, d.d3);
  return {};
}

PiecewiseLinear ReachCurve::Build(double arm_length, double height) const {
  const std::string violation = Violation(arm_length, height);
  VAHF_CHECK(violation.empty(), violation);
  const Breakpoints d = BreakpointsFor(arm_length, height);
  return PiecewiseLinear({{0.0, 1.0}, {d.d1, 1.0}, {d.d2, value_at_d2}, {d.d3, 0.0}});
}

}  // namespace vahf::human
