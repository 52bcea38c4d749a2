// A piecewise-linear curve y(x) through knots with strictly increasing x,
// held constant outside the first and last knot. The paper gives the factor
// curves of Figs. 3-5 only as pictures; vahf builds each from named breakpoints
// (see human/factor_curves.h) with this one mechanism.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vahf {

class PiecewiseLinear {
 public:
  struct Knot {
    double x;
    double y;
  };

  // Knots must be finite with strictly increasing x (at least one knot); a
  // violation is a bug in the caller, which validates user breakpoints first.
  explicit PiecewiseLinear(std::vector<Knot> knots);

  double operator()(double x) const;
  const std::vector<Knot>& knots() const { return knots_; }

  // Empty when knots are valid, else the rule they break (for validation).
  static std::string Violation(const std::vector<Knot>& knots);

 private:
  std::vector<Knot> knots_;
};

}  // namespace vahf
