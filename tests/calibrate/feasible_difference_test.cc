// Differences that stay in the valid region: Ceres' bits where both sides
// are valid, one side where only one is, a shorter step where neither is,
// and no evaluation outside the region at all.
#include "vahf/calibrate/feasible_difference.h"

#include <ceres/cost_function.h>
#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace vahf::calibrate {
namespace {

// r = (x0^2 + 3 x1, sin x0 x1), valid where x0 < 1: every call checked.
struct Model {
  int invalid_calls = 0;
  bool operator()(const double* x, double* r) {
    if (!(x[0] < 1.0)) ++invalid_calls;
    r[0] = x[0] * x[0] + 3 * x[1];
    r[1] = std::sin(x[0] * x[1]);
    return true;
  }
};

struct CeresFunctor {
  Model* model;
  bool operator()(double const* const* x, double* r) const { return (*model)(x[0], r); }
};

std::unique_ptr<ceres::CostFunction> MakeCost(Model* model, double relative_step,
                                              double limit,
                                              std::shared_ptr<DifferenceCounts> counts) {
  return MakeFeasibleDifferenceCost(
      2, 2, relative_step, [model](const double* x, double* r) { return (*model)(x, r); },
      [limit](const double* x) { return x[0] < limit; }, std::move(counts));
}

TEST(FeasibleDifference, InsideTheRegionItHasCeresCentralDifferencesBits) {
  Model model;
  const auto counts = std::make_shared<DifferenceCounts>();
  const auto cost = MakeCost(&model, 0.05, 1.0, counts);
  ceres::NumericDiffOptions options;
  options.relative_step_size = 0.05;
  ceres::DynamicNumericDiffCostFunction<CeresFunctor, ceres::CENTRAL> ceres_cost(
      new CeresFunctor{&model}, ceres::TAKE_OWNERSHIP, options);
  ceres_cost.AddParameterBlock(2);
  ceres_cost.SetNumResiduals(2);
  const double x[2] = {0.3, -0.7};
  const double* parameters[1] = {x};
  double r[2], j[4], rc[2], jc[4];
  double* jacobian[1] = {j};
  double* jacobian_ceres[1] = {jc};
  ASSERT_TRUE(cost->Evaluate(parameters, r, jacobian));
  ASSERT_TRUE(ceres_cost.Evaluate(parameters, rc, jacobian_ceres));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(j[i], jc[i]) << i;
  EXPECT_EQ(counts->central, 2);
  EXPECT_EQ(counts->one_sided, 0);
}

TEST(FeasibleDifference, AtTheRegionsEdgeItDiffersOneSidedAndNeverSteps) {
  Model model;
  const auto counts = std::make_shared<DifferenceCounts>();
  const auto cost = MakeCost(&model, 0.05, 1.0, counts);
  const double x[2] = {0.99, 2.0};  // x0 + 5 % lies past x0 < 1
  const double* parameters[1] = {x};
  double r[2], j[4];
  double* jacobian[1] = {j};
  ASSERT_TRUE(cost->Evaluate(parameters, r, jacobian));
  EXPECT_EQ(model.invalid_calls, 0);
  // The backward difference of x0^2 over delta = 0.0495: 2 x0 - delta.
  const double delta = 0.99 * 0.05;
  EXPECT_NEAR(j[0], 2 * 0.99 - delta, 1e-12);
  EXPECT_NEAR(j[1], 3.0, 1e-12);  // x1: central, exact for a linear term
  EXPECT_EQ(counts->one_sided, 1);
  EXPECT_EQ(counts->central, 1);
}

TEST(FeasibleDifference, WhereNeitherSideIsValidItShortensTheStep) {
  Model model;
  const auto counts = std::make_shared<DifferenceCounts>();
  // Valid only on (0.99, 1): both sides of a 5 % step leave it.
  const auto cost = MakeFeasibleDifferenceCost(
      2, 2, 0.05, [&model](const double* x, double* r) { return model(x, r); },
      [](const double* x) { return x[0] > 0.99 && x[0] < 1.0; }, counts);
  const double x[2] = {0.995, 1.0};
  const double* parameters[1] = {x};
  double r[2], j[4];
  double* jacobian[1] = {j};
  ASSERT_TRUE(cost->Evaluate(parameters, r, jacobian));
  EXPECT_EQ(model.invalid_calls, 0);
  EXPECT_NEAR(j[0], 2 * 0.995, 1e-4);
  EXPECT_EQ(counts->shortened, 1);
}

TEST(FeasibleDifference, APointOutsideTheRegionIsRefusedUnevaluated) {
  Model model;
  const auto cost = MakeCost(&model, 0.05, 1.0, nullptr);
  const double x[2] = {1.5, 0.0};
  const double* parameters[1] = {x};
  double r[2];
  EXPECT_FALSE(cost->Evaluate(parameters, r, nullptr));
  EXPECT_EQ(model.invalid_calls, 0);
}

}  // namespace
}  // namespace vahf::calibrate
