// One-parameter minimisation of a cost that may be piecewise constant: a
// bracket found by walking downhill, then GSL's golden-section minimiser
// inside it (docs/calibration.md, "Solvers").
//
// Why not Levenberg-Marquardt alone. A success rate over a handful of
// cycles, on common random numbers, is a step function of A_max: each cycle
// flips once. Ceres' trust region then rejects step after step, and each
// rejected candidate of a central-difference Jacobian costs three design
// evaluations: fitting A_max to the paper's success rates took 96
// evaluations (24 min on 2 cores). Bracketing and golden section use the
// cost's values only, one evaluation per iterate, and stop when the bracket
// is narrower than the tolerance. Golden section rather than Brent: Brent's
// parabolic steps assume a smooth cost, and near its best point it probes
// within sqrt(machine epsilon), a whole design evaluation that a step
// function cannot tell from the last (measured: a duplicate evaluation in
// each kappa search of experiments/calibrate_paper.json).
//
// The walk (as Numerical Recipes' mnbrak, Press et al. 2007, Sec. 10.3):
// from the start, steps that grow by the golden ratio in the direction of
// descent until the lowest cost seen has a strictly higher one on each side,
// or the walk reaches a bound. Ties (a plateau) are walked across, since GSL
// needs f(m) < f(a) and f(m) < f(b). When one side stays flat up to its bound,
// the gap between the other side's higher point and the flat run (which the
// growing steps may have jumped, with a narrow dip in it) is bisected. For a parameter
// whose lower bound is positive the search runs in log(x), where a factor is a step.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>

namespace vahf::calibrate {

struct BracketedSearch {
  double estimate = 0;     // the lowest cost's parameter value
  double cost = 0;         // there
  bool converged = false;  // the bracket closed to the tolerance
  // No higher cost on one side up to its bound (flat or falling there): the
  // minimum is not bracketed, and `estimate` is the lowest cost seen.
  bool at_bound = false;
  int iterations = 0;  // golden-section iterations
  // The final bracket (lower, best, upper), in the parameter's values: a
  // later search with other weights may start from it.
  std::array<double, 3> bracket = {0, 0, 0};
  std::string log;  // one line per walk step and iteration
};

// Minimises `cost` over [lower, upper] from `start`. `hint`, if given and
// still a strict bracket of `cost`, replaces the walk. Stops when the bracket
// is narrower than `tolerance` times the estimate (log: a factor 1 +
// tolerance), or after `max_iterations` Brent iterations. A non-finite cost
// counts as higher than any finite one.
BracketedSearch MinimizeBracketed(const std::function<double(double)>& cost, double lower,
                                  double upper, double start, double tolerance,
                                  int max_iterations,
                                  const std::optional<std::array<double, 3>>& hint = {});

// The profile interval of a one-parameter cost about its minimum: the values
// whose cost is at most `rise` above `cost_at_estimate` (for a cost of 1/2
// the sum of whitened squared residuals, rise = chi^2_1(0.95) / 2 gives the
// 95 % likelihood-ratio interval: S. S. Wilks, Ann. Math. Statist. 9, 1938;
// D. J. Venzon and S. H. Moolgavkar, Appl. Statist. 37, 1988). Unlike a
// covariance from the cost's slope at the estimate, it needs no derivative,
// so it holds for a piecewise constant cost. Each side is walked from the
// estimate by steps that start at `first_step` of the value (a factor 1 +
// first_step where the search runs in log(x)) and grow by the golden ratio
// until the cost passes the rise or the walk reaches the bound (the side is
// then open: the data do not bound it there); then the crossing is bisected
// to `tolerance` of the value, as MinimizeBracketed's bracket. A non-finite
// cost counts as past the rise.
struct ProfileInterval {
  double lower = 0, upper = 0;
  bool open_lower = false,
       open_upper = false;  // the cost stays within the rise up to the bound
  int evaluations = 0;      // calls of the cost
  std::string log;          // one line per call
};
ProfileInterval ProfileBounds(const std::function<double(double)>& cost, double lower,
                              double upper, double estimate, double cost_at_estimate,
                              double rise, double first_step, double tolerance);

}  // namespace vahf::calibrate
