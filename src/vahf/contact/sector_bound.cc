#include "vahf/contact/sector_bound.h"

#include <algorithm>
#include <cmath>

namespace vahf::contact {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Whether u points into the bound's arc.
bool IntoArc(const SectorBound& s, const Eigen::Vector2d& u) {
  return s.width <= M_PI ? Cross(s.from, u) >= 0 && Cross(u, s.to) >= 0
                         : !(Cross(s.to, u) > 0 && Cross(u, s.from) > 0);
}

// The least and greatest e(phi) . u over the bound's arc, |u| = norm: +-|u|
// where u (or -u) points into the arc, otherwise at one of its ends (e . u is
// unimodal on the circle).
struct Range {
  double min, max;
};
Range ArcRange(const SectorBound& s, const Eigen::Vector2d& u, double norm) {
  if (s.width >= kTwoPi) return {-norm, norm};
  const double a = s.from.dot(u), b = s.to.dot(u);
  return {IntoArc(s, -u) ? -norm : std::min(a, b), IntoArc(s, u) ? norm : std::max(a, b)};
}

// The extremes of rho * x over rho in [rho_min, rho_max] for x of known sign.
double RhoTimesMax(const SectorBound& s, double x) {
  return x >= 0 ? s.rho_max * x : s.rho_min * x;
}
double RhoTimesMin(const SectorBound& s, double x) {
  return x < 0 ? s.rho_max * x : s.rho_min * x;
}

}  // namespace

SectorBound BoundSector(const std::vector<Eigen::Vector3d>& points) {
  SectorBound s;
  s.rho_min = s.zeta_min = INFINITY;
  s.rho_max = s.zeta_max = -INFINITY;
  std::vector<double> phi;
  bool on_axis = false;
  for (const Eigen::Vector3d& p : points) {
    const double rho = std::hypot(p.x(), p.y());
    s.rho_min = std::min(s.rho_min, rho);
    s.rho_max = std::max(s.rho_max, rho);
    s.zeta_min = std::min(s.zeta_min, p.z());
    s.zeta_max = std::max(s.zeta_max, p.z());
    if (rho > 0)
      phi.push_back(std::atan2(p.y(), p.x()));
    else
      on_axis = true;
  }
  if (on_axis || phi.empty()) return s;  // every azimuth
  std::sort(phi.begin(), phi.end());
  // The widest gap between consecutive azimuths, the wrap-around one included;
  // the arc is the rest of the circle.
  double gap = kTwoPi - (phi.back() - phi.front());
  double start = phi.front();
  for (std::size_t k = 1; k < phi.size(); ++k)
    if (phi[k] - phi[k - 1] > gap) gap = phi[k] - phi[k - 1], start = phi[k];
  // Widened by 1e-9 rad each way, far above the rounding of cos and sin.
  constexpr double kWiden = 1e-9;
  s.width = kTwoPi - gap + 2 * kWiden;
  if (s.width >= M_PI * 1.999) {  // a nearly full circle: take all of it
    s.width = 7.0;
    return s;
  }
  s.from = Eigen::Vector2d(std::cos(start - kWiden), std::sin(start - kWiden));
  s.to = Eigen::Vector2d(std::cos(start - kWiden + s.width),
                         std::sin(start - kWiden + s.width));
  return s;
}

// With q = (rho e(phi), zeta) and p = A q + t (A the rotation):
//   p_xy = rho B e + w(zeta),  B = A's upper-left 2x2, w = zeta A_xy,z + t_xy
//   |p_xy|^2 = rho^2 |B e|^2 + 2 rho e . (B^T w) + |w|^2
//   p_z = rho e . c + A_zz zeta + t_z,  c = (A_zx, A_zy)
// A's first two columns are orthonormal, so B^T B = I - c c^T and |B e|^2 lies
// in [1 - |c|^2, 1]. e . (B^T w) is linear in zeta for each phi, so its extremes
// over the box are at zeta_min or zeta_max; |w|^2 is convex in zeta. Each term
// is bounded on its own: the sums bound |p_xy|^2 and p_z.
MeridianMap::MeridianMap(const Eigen::Isometry3d& t) {
  const Eigen::Matrix3d& a = t.linear();
  const Eigen::Vector3d& o = t.translation();
  const Eigen::Matrix2d bt = a.topLeftCorner<2, 2>().transpose();
  axis_xy_ = a.block<2, 1>(0, 2);
  offset_xy_ = o.head<2>();
  bt_axis_ = bt * axis_xy_;
  bt_offset_ = bt * offset_xy_;
  c_ = Eigen::Vector2d(a(2, 0), a(2, 1));
  c_norm_ = c_.norm();
  one_minus_c2_ = 1.0 - c_.squaredNorm();
  a_zz_ = a(2, 2);
  t_z_ = o.z();
  t_norm_ = o.norm();
}

MeridianBox MeridianMap::operator()(const SectorBound& s) const {
  const Eigen::Vector2d w0 = s.zeta_min * axis_xy_ + offset_xy_;
  const Eigen::Vector2d w1 = s.zeta_max * axis_xy_ + offset_xy_;
  const Eigen::Vector2d u0 = s.zeta_min * bt_axis_ + bt_offset_;  // B^T w0
  const Eigen::Vector2d u1 = s.zeta_max * bt_axis_ + bt_offset_;  // B^T w1
  const Range e_u0 = ArcRange(s, u0, u0.norm()), e_u1 = ArcRange(s, u1, u1.norm());
  const double hi = std::max(e_u0.max, e_u1.max), lo = std::min(e_u0.min, e_u1.min);
  const double r2_max = s.rho_max * s.rho_max + 2 * RhoTimesMax(s, hi) +
                        std::max(w0.squaredNorm(), w1.squaredNorm());
  const double r2_min = s.rho_min * s.rho_min * one_minus_c2_ + 2 * RhoTimesMin(s, lo);
  const double zz0 = a_zz_ * s.zeta_min, zz1 = a_zz_ * s.zeta_max;
  const Range e_c = ArcRange(s, c_, c_norm_);
  const double z_max = RhoTimesMax(s, e_c.max) + std::max(zz0, zz1) + t_z_;
  const double z_min = RhoTimesMin(s, e_c.min) + std::min(zz0, zz1) + t_z_;
  const double margin =
      1e-9 + 1e-12 * (s.rho_max + std::max(std::abs(s.zeta_min), std::abs(s.zeta_max)) +
                      t_norm_);
  return {std::sqrt(std::max(0.0, r2_min)) - margin,
          std::sqrt(std::max(0.0, r2_max)) + margin, z_min - margin, z_max + margin};
}

}  // namespace vahf::contact
