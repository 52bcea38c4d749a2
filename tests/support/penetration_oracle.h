// An independent geometric check of contact resolution (tests only): how deep
// the true surface of one solid of revolution lies inside another at given
// poses, computed from the profiles alone, with none of the contact model's
// code (no SignedDistance, no shells, no rims, no trees).
//
// Depth of a surface point inside a solid of revolution: the point's radius
// and height in the solid's frame, (rho, zeta), and the 2-D distance from it
// to the profile polygon's surface edges (edges on the axis are interior),
// when the crossing number says it is inside. The deepest point of a surface
// inside the other solid lies on an edge circle of either profile (a rim:
// where a corner pokes into the other) or inside a face; rims are searched on
// a 0.25 deg grid refined by golden section, faces on a grid of at most
// `face_step` along each profile edge and 1 deg around.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "vahf/geometry/shape.h"

namespace vahf::testing {

class RevolvedSolid {
 public:
  explicit RevolvedSolid(const geometry::RevolvedProfile& p) : v_(p.vertices) {
    for (const auto& q : v_) {
      r_max_ = std::max(r_max_, q.r);
      z_lo_ = std::min(z_lo_, q.z);
      z_hi_ = std::max(z_hi_, q.z);
    }
  }

  // Depth (m, > 0) of the point (rho, zeta) inside the solid; <= 0 outside.
  double Depth(double rho, double zeta) const {
    if (rho >= r_max_ || zeta <= z_lo_ || zeta >= z_hi_) return 0.0;
    bool inside = false;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < v_.size(); ++k) {
      const auto& a = v_[k];
      const auto& b = v_[(k + 1) % v_.size()];
      if ((a.z > zeta) != (b.z > zeta) &&
          rho < a.r + (zeta - a.z) / (b.z - a.z) * (b.r - a.r))
        inside = !inside;
      if (a.r == 0.0 && b.r == 0.0) continue;  // on the axis: not surface
      const double er = b.r - a.r, ez = b.z - a.z;
      const double t = std::clamp(
          ((rho - a.r) * er + (zeta - a.z) * ez) / (er * er + ez * ez), 0.0, 1.0);
      best = std::min(best, std::hypot(rho - (a.r + t * er), zeta - (a.z + t * ez)));
    }
    return inside ? best : 0.0;
  }

  // Depth of a world point inside the solid standing at `pose`.
  double DepthAt(const Eigen::Isometry3d& pose_inverse, const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = pose_inverse * p;
    return Depth(std::hypot(q.x(), q.y()), q.z());
  }

  const std::vector<geometry::ProfilePoint>& vertices() const { return v_; }

 private:
  std::vector<geometry::ProfilePoint> v_;
  double r_max_ = 0, z_lo_ = std::numeric_limits<double>::infinity(), z_hi_ = -z_lo_;
};

// The deepest point of `surface` (at pose a) inside `solid` (at pose b), m.
inline double SurfaceDepthInside(const RevolvedSolid& surface, const Eigen::Isometry3d& a,
                                 const RevolvedSolid& solid, const Eigen::Isometry3d& b,
                                 double face_step) {
  const Eigen::Isometry3d b_inv = b.inverse();
  const auto depth = [&](double r, double z, double phi) {
    return solid.DepthAt(b_inv,
                         a * Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z));
  };
  double deepest = 0;
  // Rims: each profile vertex off the axis, around its circle.
  for (const auto& q : surface.vertices()) {
    if (q.r == 0.0) continue;
    constexpr int kGrid = 1440;  // 0.25 deg
    int best_j = -1;
    double best = 0;
    for (int j = 0; j < kGrid; ++j) {
      const double d = depth(q.r, q.z, 2 * M_PI * j / kGrid);
      if (d > best) best = d, best_j = j;
    }
    if (best_j < 0) continue;
    double lo = 2 * M_PI * (best_j - 1) / kGrid, hi = 2 * M_PI * (best_j + 1) / kGrid;
    const double g = (std::sqrt(5.0) - 1) / 2;  // golden section on the bracketing cells
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = depth(q.r, q.z, x1), f2 = depth(q.r, q.z, x2);
    for (int it = 0; it < 40; ++it) {
      if (f1 > f2) {
        hi = x2, x2 = x1, f2 = f1;
        x1 = hi - g * (hi - lo), f1 = depth(q.r, q.z, x1);
      } else {
        lo = x1, x1 = x2, f1 = f2;
        x2 = lo + g * (hi - lo), f2 = depth(q.r, q.z, x2);
      }
    }
    deepest = std::max({deepest, best, f1, f2});
  }
  // Faces: a grid along each surface edge and around.
  const auto& v = surface.vertices();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const auto& p0 = v[k];
    const auto& p1 = v[(k + 1) % v.size()];
    if (p0.r == 0.0 && p1.r == 0.0) continue;
    const double length = std::hypot(p1.r - p0.r, p1.z - p0.z);
    const int along = std::max(2, static_cast<int>(std::ceil(length / face_step)));
    for (int i = 1; i < along; ++i) {
      const double t = static_cast<double>(i) / along;
      const double r = p0.r + t * (p1.r - p0.r), z = p0.z + t * (p1.z - p0.z);
      for (int j = 0; j < 360; ++j)
        deepest = std::max(deepest, depth(r, z, M_PI * j / 180));
    }
  }
  return deepest;
}

// Penetration of two solids of revolution: the deeper of each one's surface
// inside the other, m.
inline double Penetration(const RevolvedSolid& a, const Eigen::Isometry3d& pose_a,
                          const RevolvedSolid& b, const Eigen::Isometry3d& pose_b,
                          double face_step = 1e-3) {
  return std::max(SurfaceDepthInside(a, pose_a, b, pose_b, face_step),
                  SurfaceDepthInside(b, pose_b, a, pose_a, face_step));
}

}  // namespace vahf::testing
