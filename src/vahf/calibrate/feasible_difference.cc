#include "vahf/calibrate/feasible_difference.h"

#include <ceres/cost_function.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace vahf::calibrate {
namespace {

// Halvings of a step neither of whose sides is valid: 2^-20 of a 5 % step
// is 5e-8 of the value, far below what a Monte Carlo objective resolves.
constexpr int kMaxHalvings = 20;

class FeasibleDifferenceCost : public ceres::CostFunction {
 public:
  FeasibleDifferenceCost(int parameters, int residuals, double relative_step,
                         DifferenceResiduals f, ValidRegion valid,
                         std::shared_ptr<DifferenceCounts> counts)
      : relative_step_(relative_step),
        f_(std::move(f)),
        valid_(std::move(valid)),
        counts_(std::move(counts)) {
    mutable_parameter_block_sizes()->push_back(parameters);
    set_num_residuals(residuals);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double relative_step_;
  DifferenceResiduals f_;
  ValidRegion valid_;
  std::shared_ptr<DifferenceCounts> counts_;
};

bool FeasibleDifferenceCost::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  const int p = parameter_block_sizes()[0];
  const int m = num_residuals();
  const double* x0 = parameters[0];
  if (!valid_(x0) || !f_(x0, residuals)) return false;
  if (jacobians == nullptr || jacobians[0] == nullptr) return true;
  double* jacobian = jacobians[0];  // row-major, m x p
  std::vector<double> x(x0, x0 + p), plus(static_cast<std::size_t>(m)),
      minus(static_cast<std::size_t>(m));
  // Ceres' least step (internal/numeric_diff.h): no step below sqrt(eps).
  const double min_step = std::sqrt(std::numeric_limits<double>::epsilon());
  for (int j = 0; j < p; ++j) {
    double delta = std::max(min_step, std::abs(x0[j]) * relative_step_);
    bool done = false;
    for (int halving = 0; halving <= kMaxHalvings && !done; ++halving) {
      x[j] = x0[j] + delta;
      const bool has_plus = valid_(x.data()) && f_(x.data(), plus.data());
      x[j] = x0[j] - delta;
      const bool has_minus = valid_(x.data()) && f_(x.data(), minus.data());
      x[j] = x0[j];
      // Ceres' arithmetic, so that a central difference has Ceres' bits.
      double one_over_delta = 1.0 / delta;
      if (has_plus && has_minus) {
        one_over_delta /= 2;
        for (int i = 0; i < m; ++i)
          jacobian[i * p + j] = (plus[i] - minus[i]) * one_over_delta;
      } else if (has_plus) {
        for (int i = 0; i < m; ++i)
          jacobian[i * p + j] = (plus[i] - residuals[i]) * one_over_delta;
      } else if (has_minus) {
        for (int i = 0; i < m; ++i)
          jacobian[i * p + j] = (residuals[i] - minus[i]) * one_over_delta;
      } else {
        delta *= 0.5;
        continue;
      }
      done = true;
      if (counts_) {
        if (has_plus && has_minus)
          ++counts_->central;
        else
          ++counts_->one_sided;
        if (halving > 0) ++counts_->shortened;
      }
    }
    if (!done) {
      if (counts_) ++counts_->failed;
      return false;
    }
  }
  return true;
}

}  // namespace

std::unique_ptr<ceres::CostFunction> MakeFeasibleDifferenceCost(
    int parameters, int residuals, double relative_step, DifferenceResiduals f,
    ValidRegion valid, std::shared_ptr<DifferenceCounts> counts) {
  return std::make_unique<FeasibleDifferenceCost>(parameters, residuals, relative_step,
                                                  std::move(f), std::move(valid),
                                                  std::move(counts));
}

}  // namespace vahf::calibrate
