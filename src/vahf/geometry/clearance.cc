#include "vahf/geometry/clearance.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vahf::geometry {
namespace {

constexpr double kCoaxialTolerance = 1e-9;  // rad and m
constexpr double kMinOverlap = 1e-6;        // m of axial overlap that makes a fit

// The profile's cylindrical faces, z mapped by z' = offset + sign * z.
std::vector<CylindricalFace> Cylinders(const RevolvedProfile& p, double offset,
                                       double sign) {
  std::vector<CylindricalFace> out = CylindricalFaces(p);
  for (CylindricalFace& f : out) {
    const double z1 = offset + sign * f.z_lo, z2 = offset + sign * f.z_hi;
    f.z_lo = std::min(z1, z2);
    f.z_hi = std::max(z1, z2);
  }
  return out;
}

}  // namespace

std::vector<CylindricalFace> CylindricalFaces(const RevolvedProfile& p) {
  std::vector<CylindricalFace> out;
  const auto& v = p.vertices;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const ProfilePoint a = v[k], b = v[(k + 1) % v.size()];
    if (a.r != b.r || a.r <= 0.0 || a.z == b.z) continue;
    // Counter-clockwise: the outward normal's r part is dz / length, so an
    // edge going up (dz > 0) faces away from the axis.
    out.push_back({a.r, std::min(a.z, b.z), std::max(a.z, b.z), b.z > a.z});
  }
  return out;
}

std::optional<double> SmallestRadialClearance(const Shape& a_shape,
                                              const Eigen::Isometry3d& a,
                                              const Shape& b_shape,
                                              const Eigen::Isometry3d& b) {
  const std::optional<RadialFit> fit = SmallestRadialFit(a_shape, a, b_shape, b);
  if (!fit) return std::nullopt;
  return fit->clearance;
}

std::optional<RadialFit> SmallestRadialFit(const Shape& a_shape,
                                           const Eigen::Isometry3d& a,
                                           const Shape& b_shape,
                                           const Eigen::Isometry3d& b) {
  const auto* pa = std::get_if<RevolvedProfile>(&a_shape);
  const auto* pb = std::get_if<RevolvedProfile>(&b_shape);
  if (!pa || !pb) return std::nullopt;
  const Eigen::Vector3d axis_a = a.linear().col(2), axis_b = b.linear().col(2);
  if (axis_a.cross(axis_b).norm() > kCoaxialTolerance) return std::nullopt;
  const Eigen::Vector3d d = a.translation() - b.translation();
  if ((d - d.dot(axis_b) * axis_b).norm() > kCoaxialTolerance) return std::nullopt;
  // Common axial coordinate: b's z.
  const std::vector<CylindricalFace> ca =
      Cylinders(*pa, d.dot(axis_b), axis_a.dot(axis_b) > 0 ? 1.0 : -1.0);
  const std::vector<CylindricalFace> cb = Cylinders(*pb, 0.0, 1.0);
  std::optional<RadialFit> best;
  for (const CylindricalFace& x : ca) {
    for (const CylindricalFace& y : cb) {
      const double overlap = std::min(x.z_hi, y.z_hi) - std::max(x.z_lo, y.z_lo);
      if (overlap <= kMinOverlap || x.faces_out == y.faces_out) continue;
      const CylindricalFace& shaft = x.faces_out ? x : y;
      const CylindricalFace& bore = x.faces_out ? y : x;
      const double gap = bore.r - shaft.r;
      if (gap > 0 && (!best || gap < best->clearance)) best = RadialFit{gap, bore.r};
    }
  }
  return best;
}

}  // namespace vahf::geometry
