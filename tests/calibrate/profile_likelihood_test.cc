// The profile interval's end search (profile_likelihood.h) on profiles known
// in closed form.
#include "vahf/calibrate/profile_likelihood.h"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>
#include <limits>

namespace vahf::calibrate {
namespace {

// chi^2_1(0.95) / 2: the end lies where z = sqrt(2 rise) = 1.95996.
constexpr double kRise = 1.920729410347062;
constexpr double kZ = 1.959963984540054;

TEST(ProfileEnd, AQuadraticProfileEndsAtTheWaldEndInOneCall) {
  // rise = (v - 2)^2 / (2 * 0.5^2): the end is 2 +- 1.96 * 0.5.
  int calls = 0;
  const auto rise = [&](double v) {
    ++calls;
    return (v - 2) * (v - 2) / 0.5;
  };
  // A first guess 1 % beyond the end is accepted (an end is never inside).
  const ProfileEnd up =
      ProfileEndToward(rise, 2.0, 10.0, 2.0 + 1.01 * kZ * 0.5, kRise, 6);
  EXPECT_NEAR(up.bound, 2.0 + 1.01 * kZ * 0.5, 1e-12);
  EXPECT_FALSE(up.open);
  EXPECT_TRUE(up.reached);
  EXPECT_EQ(calls, 1);
  // From a first guess three times too narrow, the secant on z lands on
  // the end at its second call (z is linear in v).
  calls = 0;
  const ProfileEnd down =
      ProfileEndToward(rise, 2.0, -10.0, 2.0 - kZ * 0.5 / 3, kRise, 6);
  EXPECT_NEAR(down.bound, 2.0 - kZ * 0.5, 1e-9);
  EXPECT_EQ(calls, 2);
}

TEST(ProfileEnd, ACurvedValleyGivesTheEndTheWaldIntervalMisses) {
  // A cost whose valley bends, 1/2 [(y - x^2)^2 / s^2 + (x - 1)^2]: the
  // profile over y is (x - 1)^2 / 2 exactly (y follows x^2), so the end of
  // x is 1 + 1.96 whatever s, while the curvature of the cost at the
  // minimum in the direction of x alone is (1 + 4 x^2 / s^2) and a narrow
  // valley (s = 0.2) gives a conditional interval 10 times too short.
  const auto profile = [](double x) { return 0.5 * (x - 1) * (x - 1); };
  const ProfileEnd end = ProfileEndToward(profile, 1.0, 100.0, 1.0 + kZ / 10, kRise, 8);
  EXPECT_NEAR(end.bound, 1.0 + kZ, 0.05 * kZ);
  EXPECT_TRUE(end.reached);
  // Extrapolation grows at most 4-fold a call: 0.196, 0.78, then the end.
  EXPECT_LE(end.points.size(), 3u);
}

TEST(ProfileEnd, AFlatSideIsOpenAtItsEdge) {
  // The rise saturates below the target: the data do not bound this side.
  const auto rise = [](double v) { return 1.5 * (1 - std::exp(-v)); };
  const ProfileEnd end = ProfileEndToward(rise, 0.0, 5.0, 0.3, kRise, 8);
  EXPECT_TRUE(end.open);
  EXPECT_EQ(end.bound, 5.0);
}

TEST(ProfileEnd, AnEstimateAtItsEdgeIsOpenWithoutACall) {
  int calls = 0;
  const ProfileEnd end = ProfileEndToward(
      [&](double) {
        ++calls;
        return 0.0;
      },
      3.0, 3.0, 3.5, kRise, 4);
  EXPECT_TRUE(end.open);
  EXPECT_EQ(calls, 0);
}

TEST(ProfileEnd, ANonFiniteRiseCountsAsBeyondAndIsBisected) {
  // No value beyond 1.2 (the model is undefined there), the target at 1.5:
  // the end is where the rise stops, within the search's last bracket.
  const auto rise = [](double v) {
    return v > 1.2 ? std::numeric_limits<double>::quiet_NaN() : v * v;
  };
  const ProfileEnd end = ProfileEndToward(rise, 0.0, 10.0, 2.0, kRise, 10);
  EXPECT_FALSE(end.open);
  EXPECT_GT(end.bound, 1.0);
  EXPECT_LE(end.bound, 1.3);
}

TEST(ProfileEnd, AJumpInTheCostIsBisectedAndItsEndWasEvaluated) {
  // A residual that changes branch at v = 0.437 (as a chamfer contact that
  // starts or stops): the rise jumps from well inside to well beyond the
  // target there, so the end is the jump. Regula falsi across it keeps its
  // inside end; bisection closes in. When the calls run out the bound is a
  // point the search evaluated beyond the target: an interpolation across
  // the jump would be an end no call has shown to be outside.
  constexpr double kJump = 0.437;
  const auto rise = [&](double v) { return v < kJump ? 2 * v : 6.0; };
  for (int calls : {6, 8, 12}) {
    const ProfileEnd end = ProfileEndToward(rise, 0.0, 10.0, 1.0, kRise, calls);
    EXPECT_TRUE(end.reached);
    EXPECT_FALSE(end.open);
    EXPECT_GE(end.bound, kJump) << calls << " calls";
    EXPECT_LE(end.bound, kJump + 0.05) << calls << " calls";
    bool evaluated = false;
    for (const auto& [v, r] : end.points) evaluated |= v == end.bound && r >= kRise;
    EXPECT_TRUE(evaluated) << calls << " calls: the bound " << end.bound;
  }
}

TEST(ProfileEnd, RunningOutOfCallsInsideSaysSo) {
  // A profile that rises slowly: two calls cannot reach the target.
  const auto rise = [](double v) { return 1e-4 * v * v; };
  const ProfileEnd end = ProfileEndToward(rise, 0.0, 1e9, 1.0, kRise, 2);
  EXPECT_FALSE(end.reached);
  EXPECT_FALSE(end.open);
  EXPECT_EQ(end.bound, end.points.back().first);
}

}  // namespace
}  // namespace vahf::calibrate

namespace vahf::calibrate {
namespace {

// Linear residuals a y - b, three of two parameters.
Eigen::MatrixXd LinearA() {
  Eigen::MatrixXd a(3, 2);
  a << 1, 0, 0, 2, 1, 1;
  return a;
}
const Eigen::Vector3d kLinearB(1, 2, 4);

// Linear residuals: one Gauss-Newton step on the exact Jacobian lands on
// the least-squares solution, and the cost there is the residual's.
TEST(SecantLeastSquares, LinearResidualsAreSolvedInOneStep) {
  const Eigen::MatrixXd a = LinearA();
  const Eigen::Vector3d& b = kLinearB;
  const ResidualVector f = [&](const Eigen::VectorXd& y, Eigen::VectorXd* r) {
    *r = a * y - b;
    return true;
  };
  Eigen::MatrixXd j = a;
  const Eigen::Vector2d lower(-10, -10), upper(10, 10);
  const SecantFit fit =
      SecantLeastSquares(f, Eigen::Vector2d(0, 0), &j, lower, upper, 4, 1e-12);
  const Eigen::VectorXd best = a.colPivHouseholderQr().solve(b);
  EXPECT_NEAR((fit.y - best).norm(), 0, 1e-12);
  EXPECT_NEAR(fit.cost, 0.5 * (a * best - b).squaredNorm(), 1e-12);
  EXPECT_EQ(fit.evaluations, 2);  // the start and the step: the model promises no more
}

// Rosenbrock's valley as residuals (10 (y2 - y1^2), 1 - y1) from a wrong
// Jacobian (that at the origin): Broyden's updates find the valley's floor
// well enough that the cost falls by orders of magnitude in a few calls.
TEST(SecantLeastSquares, BroydensUpdatesFollowACurvedValley) {
  const ResidualVector f = [](const Eigen::VectorXd& y, Eigen::VectorXd* r) {
    r->resize(2);
    (*r)(0) = 10 * (y(1) - y(0) * y(0));
    (*r)(1) = 1 - y(0);
    return true;
  };
  Eigen::MatrixXd j(2, 2);
  j << 0, 10, -1, 0;  // exact at y1 = 0
  const Eigen::Vector2d lower(-5, -5), upper(5, 5);
  const SecantFit fit =
      SecantLeastSquares(f, Eigen::Vector2d(0.5, 0.0), &j, lower, upper, 12, 1e-10);
  EXPECT_LT(fit.cost, 1e-3 * 0.5 * (6.25 + 0.25)) << fit.y.transpose();
  EXPECT_LE(fit.evaluations, 12);
}

// A step outside the valid region (no value) is halved, and the start is
// kept when no step finds a lower cost.
TEST(SecantLeastSquares, AStepWithoutAValueIsHalvedAndTheBestPointKept) {
  const ResidualVector f = [](const Eigen::VectorXd& y, Eigen::VectorXd* r) {
    if (y(0) > 0.5) return false;
    r->resize(1);
    (*r)(0) = y(0) - 1;
    return true;
  };
  Eigen::MatrixXd j = Eigen::MatrixXd::Ones(1, 1);
  const SecantFit fit = SecantLeastSquares(f, Eigen::VectorXd::Zero(1), &j,
                                           Eigen::VectorXd::Constant(1, -5),
                                           Eigen::VectorXd::Constant(1, 5), 8, 1e-12);
  // The full step (to 1) has no value; its half (0.5) does, and lowers the cost.
  EXPECT_GT(fit.y(0), 0.2);
  EXPECT_LE(fit.y(0), 0.5);
  EXPECT_LT(fit.cost, 0.5);
}

TEST(SecantLeastSquares, AStartWithoutAValueHasNoCost) {
  const ResidualVector f = [](const Eigen::VectorXd&, Eigen::VectorXd*) { return false; };
  Eigen::MatrixXd j = Eigen::MatrixXd::Ones(1, 1);
  const SecantFit fit = SecantLeastSquares(f, Eigen::VectorXd::Zero(1), &j,
                                           Eigen::VectorXd::Constant(1, -1),
                                           Eigen::VectorXd::Constant(1, 1), 8, 1e-12);
  EXPECT_TRUE(std::isnan(fit.cost));
  EXPECT_EQ(fit.evaluations, 1);
}

// Linear residuals: forward differences give the exact Jacobian; a column
// whose forward point passes its bound is differenced backward; one that
// has no value either way keeps what it had.
TEST(DifferenceColumns, ForwardBackwardOrKept) {
  const Eigen::MatrixXd a = LinearA();
  const Eigen::Vector3d& b = kLinearB;
  const Eigen::Vector2d y(1.0, 0.0);
  bool first_fixed = false;  // no value where y(0) moves
  int backward = 0;
  const ResidualVector f = [&](const Eigen::VectorXd& z, Eigen::VectorXd* r) {
    if (first_fixed && z(0) != y(0)) return false;
    backward += z(1) < y(1);
    *r = a * z - b;
    return true;
  };
  const Eigen::VectorXd r0 = a * y - b;
  // y(1) at 0 steps by 0.05 of 1; its upper bound 0.01 forces the backward step.
  const Eigen::Vector2d lower(-10, -10), upper(10, 0.01);
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(3, 2);
  DifferenceColumns(f, y, r0, lower, upper, 0.05, &j);
  EXPECT_NEAR((j - a).norm(), 0, 1e-12);
  EXPECT_EQ(backward, 1);
  first_fixed = true;
  j.setConstant(7.0);
  DifferenceColumns(f, y, r0, lower, upper, 0.05, &j);
  EXPECT_EQ(j.col(0), Eigen::Vector3d::Constant(7.0));
  EXPECT_NEAR((j.col(1) - a.col(1)).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace vahf::calibrate
