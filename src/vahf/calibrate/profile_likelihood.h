// One end of a profile-likelihood interval, found with few evaluations of
// the profile (docs/calibration.md, "Profile intervals").
//
// The 95 % profile interval of a parameter of a least-squares fit holds the
// values v whose profile, the least cost with the parameter held at v and
// the others re-fitted, rises at most chi^2_1(0.95) / 2 above the cost at
// the estimate (S. S. Wilks, Ann. Math. Statist. 9, 1938; D. J. Venzon and
// S. H. Moolgavkar, Appl. Statist. 37, 1988). Unlike the Wald interval from
// the curvature at the estimate, it follows a curved valley in which the
// parameter trades against others (A. Raue et al., Bioinformatics 25, 2009,
// "Structural and practical identifiability analysis of partially observed
// dynamical models by exploiting the profile likelihood").
//
// Each profile value costs a re-fit, so the end is found by a root search
// on the signed root z(v) = sqrt(2 rise(v)), which is linear in v where the
// cost is quadratic (D. M. Bates and D. G. Watts, Nonlinear Regression
// Analysis and Its Applications, Wiley 1988, Sec. 6.1, the profile t
// function): from a first guess (the Wald end), the secant through the
// inside points extrapolates toward z = sqrt(2 target), and once a point
// lies beyond it, regula falsi on the bracket closes in, bisecting when it
// stalls.
#pragma once
#include <Eigen/Core>
#include <functional>
#include <utility>
#include <vector>

namespace vahf::calibrate {

struct ProfileEnd {
  double bound = 0;     // an evaluated point at or beyond the target, or the edge
  bool open = false;    // the rise stays below the target up to the edge
  bool reached = true;  // false: the calls ran out with every point inside;
                        // `bound` is then the farthest of them
  std::vector<std::pair<double, double>> points;  // (value, rise), in call order
};

// The end of the profile interval from `estimate` toward `edge` (the end of
// the valid range on that side), `rise(v)` the profile's rise above the
// cost at the estimate (a non-finite rise counts as beyond the target, a
// negative one as 0), `first` the first value tried (clamped to the edge),
// at most `max_calls` calls. A point at or up to `z_tolerance` (relative)
// beyond the target's signed root ends the search: an end is never inside.
// When the calls run out with the end bracketed, the bound is the nearest
// point evaluated beyond the target, never an interpolation between them
// (across a jump of the cost one would lie inside). Regula falsi that keeps
// one end of the bracket is bisected instead (a jump, or a profile far from
// linear in the bracket).
ProfileEnd ProfileEndToward(const std::function<double(double)>& rise, double estimate,
                            double edge, double first, double target_rise, int max_calls,
                            double z_tolerance = 0.05);

// A least-squares re-fit without new derivatives, for the profile's
// re-fits: Gauss-Newton steps on a Jacobian that Broyden's rank-one update
// keeps current from the residuals the steps evaluate (C. G. Broyden, Math.
// Comp. 19, 1965; J. E. Dennis and R. B. Schnabel, Numerical Methods for
// Unconstrained Optimization and Nonlinear Equations, SIAM 1996, Sec. 8.3
// and 10.3), a step that does not lower the cost halved. One residual
// evaluation a step: a profile value costs a few design evaluations where a
// re-fit that differences its Jacobian anew costs tens
// (docs/calibration.md, Profile intervals).
struct SecantFit {
  Eigen::VectorXd y;    // the re-fitted parameters
  double cost = 0;      // 1/2 |r|^2 there; NaN when the start has no value
  int evaluations = 0;  // calls of the residuals
};
// The residuals at y; false where the model has no value (outside the valid
// region, no sample).
using ResidualVector = std::function<bool(const Eigen::VectorXd& y, Eigen::VectorXd* r)>;
// From `start` (within [lower, upper]) and `jacobian` (m x q, the residuals'
// derivatives there or nearby, updated in place), at most `max_evaluations`
// calls; stops when a step lowers the cost by less than `cost_tolerance`,
// or the linear model promises less.
SecantFit SecantLeastSquares(const ResidualVector& f, const Eigen::VectorXd& start,
                             Eigen::MatrixXd* jacobian, const Eigen::VectorXd& lower,
                             const Eigen::VectorXd& upper, int max_evaluations,
                             double cost_tolerance);

// The columns of *jacobian (m x q) anew by forward differences of `f` at y
// (where its residuals are r0) over `relative_step` of each value (of 1
// where the value is 0), backward where the forward point is outside
// [lower, upper] or has no value; a column that can be differenced neither
// way is kept. A profile value's re-fit calls it before its secant steps
// (docs/calibration.md, Profile intervals: why anew at each value).
void DifferenceColumns(const ResidualVector& f, const Eigen::VectorXd& y,
                       const Eigen::VectorXd& r0, const Eigen::VectorXd& lower,
                       const Eigen::VectorXd& upper, double relative_step,
                       Eigen::MatrixXd* jacobian);

}  // namespace vahf::calibrate
