// The radial clearance of a fit: the gap between a cylindrical face of one
// solid of revolution and a facing cylindrical face of another on the same
// axis (a rod in a bore, a sleeve on a rod), where the faces overlap along the
// axis. The contact's penetration bound is a fraction of the smallest one
// (docs/design.md decision 7).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "vahf/geometry/shape.h"

namespace vahf::geometry {

// A cylindrical face of a solid of revolution: a profile edge of constant
// radius r > 0, its axial extent in the part frame, and whether it faces
// away from the axis (a shaft) or toward it (a bore).
struct CylindricalFace {
  double r, z_lo, z_hi;
  bool faces_out;
};

// The profile's cylindrical faces, in the order of its edges.
std::vector<CylindricalFace> CylindricalFaces(const RevolvedProfile& profile);

// The smallest radial clearance (m, > 0) between `inner_or_outer` at pose
// `a` and `other` at pose `b` (part frames in the world): over pairs of
// cylindrical profile edges (constant r > 0), one facing outward and the other
// facing it from a larger radius, that overlap along the common axis by more
// than 1 micrometre. Nothing when the two are not coaxial (axes within 1e-9
// rad and 1e-9 m), when either is not a solid of revolution, or when no faces
// face each other.
std::optional<double> SmallestRadialClearance(const Shape& a_shape,
                                              const Eigen::Isometry3d& a,
                                              const Shape& b_shape,
                                              const Eigen::Isometry3d& b);

// The fit SmallestRadialClearance finds: its clearance and the radius of its
// bore (the fit's nominal radius), m.
struct RadialFit {
  double clearance = 0;
  double bore_radius = 0;
};
std::optional<RadialFit> SmallestRadialFit(const Shape& a_shape,
                                           const Eigen::Isometry3d& a,
                                           const Shape& b_shape,
                                           const Eigen::Isometry3d& b);

}  // namespace vahf::geometry
