#include "vahf/contact/point_load.h"

#include <algorithm>

namespace vahf::contact {

double NormalLaw(double k, double x0, double c, double b, double depth, double depth_rate,
                 LawSlopes* slopes) {
  if (slopes) *slopes = LawSlopes{};
  if (!(depth > 0)) return 0.0;
  // The C1 elastic law and its slope.
  const auto e = [&](double x) {
    return x < x0 ? k * x * x / (2 * x0) : k * (x - 0.5 * x0);
  };
  const auto de = [&](double x) { return x < x0 ? k * x / x0 : k; };
  double elastic;
  double slope = 0;  // d elastic / d depth, when asked for
  if (!(b > 0)) {
    elastic = e(depth);
    if (slopes) slope = de(depth);
  } else {
    const double xc = b * (1.0 - kBarrierReserve);
    const double x = std::min(depth, xc);
    const double s = 1.0 / (1.0 - x / b);  // 1 / (1 - x / b)
    elastic = e(x) * s * s;
    if (depth > xc)  // along the tangent at xc: d/dx [e h] = e' h + e h', h' = 2 s^3 / b
      elastic += (de(xc) * s * s + e(xc) * 2.0 * s * s * s / b) * (depth - xc);
    // The same product rule at x; past xc, x = xc: the tangent's slope.
    if (slopes) slope = de(x) * s * s + e(x) * 2.0 * s * s * s / b;
  }
  const double factor = 1.0 + c * depth_rate;  // Hunt and Crossley
  if (slopes && factor > 0) *slopes = LawSlopes{slope * factor, elastic * c};
  return elastic * std::max(0.0, factor);
}

double Pressure(const PenaltyLaw& p, double depth, double depth_rate, LawSlopes* slopes) {
  return NormalLaw(p.stiffness, p.onset_depth, p.dissipation, p.barrier_depth, depth,
                   depth_rate, slopes);
}

double LineLoad(const PenaltyLaw& p, double depth, double depth_rate, LawSlopes* slopes) {
  return NormalLaw(p.line_stiffness, p.onset_depth, p.dissipation, p.barrier_depth, depth,
                   depth_rate, slopes);
}

double PairFriction(double a, double b) { return a + b > 0 ? 2 * a * b / (a + b) : 0.0; }

bool AddPointLoad(const PenaltyLaw& params, const PointLoad& p, const Eigen::Vector3d& w,
                  ContactForces* out, ContactJacobian* jacobian) {
  LawSlopes slopes;
  LawSlopes* const asked = jacobian ? &slopes : nullptr;
  const double depth_rate = -p.v.dot(p.u);
  const double fn = (p.line ? LineLoad(params, p.depth, depth_rate, asked)
                            : Pressure(params, p.depth, depth_rate, asked)) *
                    p.size;
  if (!(fn > 0)) return false;
  const Eigen::Vector3d v_t = p.v - p.v.dot(p.u) * p.u;
  const double slip = v_t.norm();
  const Eigen::Vector3d ft =
      -p.mu * fn / std::max(slip, params.friction_transition_speed) * v_t;
  out->normal_force += fn * p.u;
  out->friction_force += ft;
  out->torque += p.r.cross(fn * p.u + ft);
  if (jacobian)
    AddPointJacobian({p.r, p.v, p.u, w, fn, slopes.depth * p.size, slopes.rate * p.size,
                      p.mu, params.friction_transition_speed, p.frame},
                     jacobian);
  return true;
}

}  // namespace vahf::contact
