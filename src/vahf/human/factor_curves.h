// The estimate curves of the paper's Figs. 3 (eye-sight direction f), 4
// (reachability r) and 5 (glance g). The paper shows them only as pictures and
// states their plateaus in the text; vahf makes each piecewise linear with
// named breakpoints. Defaults and the reasons for them: docs/human-factors.md.
#pragma once

#include <string>

#include "vahf/core/piecewise_linear.h"

namespace vahf::human {

// A curve over an angle in [0, 180] degrees that is 1 on a preferred plateau
// [plateau_from_deg, plateau_to_deg] and falls linearly to value_at_0 at 0 deg
// and to value_at_180 at 180 deg. Both f (Fig. 3) and g (Fig. 5) have this shape.
struct PlateauCurve {
  double value_at_0 = 0.5;
  double plateau_from_deg = 30.0;
  double plateau_to_deg = 45.0;
  double value_at_180 = 0.0;

  PiecewiseLinear Build() const;
  // Empty when valid, else the rule broken.
  std::string Violation() const;
};

// Fig. 3, eye-sight direction: "Ang in the range from 30 to 45 deg is most
// preferable (estimation is 1) and the estimation decreases over 45 deg".
inline PlateauCurve DefaultSightCurve() { return {0.5, 30.0, 45.0, 0.0}; }
// Fig. 5, glance: "Anp in the range from 30 to 90 deg is most preferable
// (estimation is 1) and the estimation decreases over 90 deg".
inline PlateauCurve DefaultGlanceCurve() { return {0.5, 30.0, 90.0, 0.0}; }

// Fig. 4, reachability against the distance from the shoulder to the part:
// 1 up to D1, falling to value_at_d2 at D2, and to 0 at D3 (beyond D3 the part
// cannot be reached with any posture). D1 = 0.85 l, D2 = 0.39 h, D3 = 0.68 h
// (Sec. 3.2.2, after Enomoto et al. [36]); l arm length, h stature, in metres.
struct ReachCurve {
  double d1_arm_fraction = 0.85;
  double d2_height_fraction = 0.39;
  double d3_height_fraction = 0.68;
  double value_at_d2 = 0.5;

  struct Breakpoints {
    double d1, d2, d3;  // m
  };
  Breakpoints BreakpointsFor(double arm_length, double height) const;
  // Requires D1 < D2 < D3 for this operator (see Violation).
  PiecewiseLinear Build(double arm_length, double height) const;
  // Empty when the curve is valid for an operator of this arm length and
  // height (D1 < D2 < D3), else the rule broken, with the numbers.
  std::string Violation(double arm_length, double height) const;
};

}  // namespace vahf::human
