#include "vahf/calibrate/profile_likelihood.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

#include "vahf/core/error.h"

namespace vahf::calibrate {
namespace {

// Extrapolation beyond the farthest inside point goes at most this many
// times its distance from the estimate, so that one flat stretch of a noisy
// profile does not throw the next point to the edge.
constexpr double kMaxGrowth = 4.0;
// Regula falsi stays this fraction of the bracket away from its ends, so
// that a profile far from linear still shrinks the bracket each call.
constexpr double kBracketMargin = 0.1;
// Regula falsi that moves the same end of the bracket this many calls in a
// row meets a profile far from linear there (across a jump of the cost,
// where one residual changes branch): the next call bisects, as the
// safeguard of Dekker's and Brent's root finders (R. P. Brent, Algorithms
// for Minimization without Derivatives, Prentice-Hall 1973, Ch. 4).
constexpr int kFalsiRun = 2;
// Halvings of a Gauss-Newton step that does not lower the cost before the
// re-fit stops where it is.
constexpr int kMaxHalvings = 3;

// The search's state along one side, in distances from the estimate: the
// farthest point inside (z below the target) and the one before it, the
// nearest beyond, and which end the last calls moved.
struct EndBracket {
  double target_z;
  double in_d = 0, in_z = 0, prev_in_d = 0, prev_in_z = 0;
  double out_d = 0, out_z = 0;
  bool beyond = false;
  int moved = 0, moved_run = 0;  // +1 inside, -1 beyond; calls in a row

  void Record(double d, double z) {
    const int side = z < target_z ? 1 : -1;
    moved_run = side == moved ? moved_run + 1 : 1;
    moved = side;
    if (side > 0) {
      prev_in_d = in_d;
      prev_in_z = in_z;
      in_d = d;
      in_z = z;
    } else {
      out_d = d;
      out_z = z;
      beyond = true;
    }
  }

  // The next distance to try: regula falsi on z in the bracket (bisection
  // when z beyond is infinite or regula falsi stalls), the secant through
  // the inside points before one lies beyond.
  double Next() const {
    if (beyond) {
      const double width = out_d - in_d;
      if (moved_run >= kFalsiRun || !std::isfinite(out_z)) return in_d + 0.5 * width;
      const double falsi = in_d + (target_z - in_z) * width / (out_z - in_z);
      return std::clamp(falsi, in_d + kBracketMargin * width,
                        out_d - kBracketMargin * width);
    }
    const double slope = (in_z - prev_in_z) / (in_d - prev_in_d);
    const double next = slope > 0 ? in_d + (target_z - in_z) / slope : kMaxGrowth * in_d;
    return std::min(next, kMaxGrowth * in_d);
  }
};

}  // namespace

ProfileEnd ProfileEndToward(const std::function<double(double)>& rise, double estimate,
                            double edge, double first, double target_rise, int max_calls,
                            double z_tolerance) {
  VAHF_CHECK(target_rise > 0 && max_calls >= 1 && z_tolerance > 0,
             "a profile end needs a positive target, calls and tolerance");
  ProfileEnd out;
  if (edge == estimate) {  // the estimate is at the end of its range
    out.bound = edge;
    out.open = true;
    return out;
  }
  const double dir = edge > estimate ? 1.0 : -1.0;
  const auto toward_edge = [&](double v) {
    return dir > 0 ? std::min(v, edge) : std::max(v, edge);
  };
  EndBracket b{std::sqrt(2 * target_rise)};
  double v = toward_edge(first);
  if (!((v - estimate) * dir > 0)) v = edge;  // a first guess on the wrong side
  for (int call = 0; call < max_calls; ++call) {
    const double r = rise(v);
    out.points.emplace_back(v, r);
    const double z = std::isfinite(r) ? std::sqrt(2 * std::max(r, 0.0))
                                      : std::numeric_limits<double>::infinity();
    // Accepted only at or beyond the target, so that an end found is never
    // inside the interval it bounds.
    if (z >= b.target_z && z <= (1 + z_tolerance) * b.target_z) {
      out.bound = v;
      return out;
    }
    b.Record((v - estimate) * dir, z);
    if (z < b.target_z && v == edge) {
      out.bound = edge;
      out.open = true;
      return out;
    }
    v = toward_edge(estimate + dir * b.Next());
  }
  if (b.beyond) {  // the nearest point evaluated beyond: never an unevaluated end
    out.bound = estimate + dir * b.out_d;
  } else {
    out.bound = estimate + dir * b.in_d;
    out.reached = false;
  }
  return out;
}

SecantFit SecantLeastSquares(const ResidualVector& f, const Eigen::VectorXd& start,
                             Eigen::MatrixXd* jacobian, const Eigen::VectorXd& lower,
                             const Eigen::VectorXd& upper, int max_evaluations,
                             double cost_tolerance) {
  VAHF_CHECK(jacobian->cols() == start.size() && max_evaluations >= 1,
             "a secant re-fit needs a Jacobian of its parameters and an evaluation");
  SecantFit out;
  out.y = start;
  Eigen::VectorXd r;
  ++out.evaluations;
  if (!f(out.y, &r)) {
    out.cost = std::nan("");
    return out;
  }
  out.cost = 0.5 * r.squaredNorm();
  int halvings = 0;
  while (out.evaluations < max_evaluations && start.size() > 0) {
    Eigen::MatrixXd& b = *jacobian;
    // The Gauss-Newton step, least squares in b s = -r (rank-revealing).
    const Eigen::VectorXd full = b.colPivHouseholderQr().solve(-r);
    const Eigen::VectorXd y =
        (out.y + std::ldexp(1.0, -halvings) * full).cwiseMax(lower).cwiseMin(upper);
    const Eigen::VectorXd s = y - out.y;
    if (!(s.squaredNorm() > 0) || !s.allFinite()) break;
    // The fall the linear model promises: none worth a call, none to find.
    if (out.cost - 0.5 * (r + b * s).squaredNorm() < cost_tolerance) break;
    Eigen::VectorXd r_new;
    ++out.evaluations;
    const bool has = f(y, &r_new) && r_new.allFinite();
    // Broyden's update: the secant condition b_new s = r_new - r.
    if (has) b += ((r_new - r) - b * s) * s.transpose() / s.squaredNorm();
    const double cost = has ? 0.5 * r_new.squaredNorm() : std::nan("");
    if (has && cost < out.cost) {
      const double fall = out.cost - cost;
      out.y = y;
      out.cost = cost;
      r = r_new;
      halvings = 0;
      if (fall < cost_tolerance) break;
    } else if (++halvings > kMaxHalvings) {
      break;
    }
  }
  return out;
}

void DifferenceColumns(const ResidualVector& residuals, const Eigen::VectorXd& y,
                       const Eigen::VectorXd& r0, const Eigen::VectorXd& lower,
                       const Eigen::VectorXd& upper, double relative_step,
                       Eigen::MatrixXd* jacobian) {
  for (Eigen::Index k = 0; k < y.size(); ++k) {
    const double h = relative_step * (y(k) != 0 ? std::abs(y(k)) : 1.0);
    for (double step : {h, -h}) {
      Eigen::VectorXd z = y;
      z(k) += step;
      if (!(z(k) >= lower(k) && z(k) <= upper(k))) continue;
      Eigen::VectorXd r;
      if (!residuals(z, &r)) continue;
      jacobian->col(k) = (r - r0) / step;
      break;
    }
  }
}

}  // namespace vahf::calibrate
