// Central differences that stay where the model is defined. A calibration's
// parameters may be tied by a rule (the reach breakpoints D1 < D2 < D3 for
// every operator of the lab) and held within bounds, and a finite difference
// must not step out of either: Ceres' numeric differentiation
// (DynamicNumericDiffCostFunction) steps x +- delta whatever the bounds and
// fails the whole Jacobian when one side cannot be evaluated, which is how a
// joint fit of D1 and kappa used to stop at its third evaluation (a 5 % step
// of D1 passed D2 for the tallest operator). This cost function differs as
// Ceres does (the same step, the same arithmetic, so the same bits) where
// both sides are valid, one-sidedly where only one is, and halves the step
// where neither is. A point outside the valid region itself is refused
// (Evaluate returns false), which Ceres' trust-region solver takes as a
// failed step and answers with a shorter one (Ceres Solver documentation,
// "Modeling Non-linear Least Squares", CostFunction::Evaluate): the solver
// is told where the region ends.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

namespace ceres {
class CostFunction;
}  // namespace ceres

namespace vahf::calibrate {

// How often the differences had to leave the central form, over the cost
// functions that share one.
struct DifferenceCounts {
  std::int64_t central = 0, one_sided = 0, shortened = 0, failed = 0;
};

// The residuals at a parameter vector; false where there is no value.
using DifferenceResiduals = std::function<bool(const double* x, double* residuals)>;
// Whether a parameter vector lies in the valid region (bounds and rules).
using ValidRegion = std::function<bool(const double* x)>;

// A cost function of one parameter block of `parameters` values and
// `residuals` residuals, differenced as above; the step of parameter j is
// max(sqrt(eps), relative_step |x_j|), as Ceres'. `counts`, if given, adds
// up how each column was differenced.
std::unique_ptr<ceres::CostFunction> MakeFeasibleDifferenceCost(
    int parameters, int residuals, double relative_step, DifferenceResiduals f,
    ValidRegion valid, std::shared_ptr<DifferenceCounts> counts = nullptr);

}  // namespace vahf::calibrate
