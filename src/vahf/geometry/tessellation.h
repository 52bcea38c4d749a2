// Triangle meshes of part shapes (geometry::Shape), for ray casting (Eq. 1).
//
// A solid of revolution is tessellated by revolving its profile polygon in n
// equal steps about the part's z axis; every vertex lies on the exact surface
// and the only error is the chord of each circle, at most
// r_max (1 - cos(pi / n)). n is the least count meeting a chord tolerance:
//
//   n = max(3, ceil(pi / acos(1 - tol / r_max)))      (tol < 2 r_max)
//
// (3 when tol >= 2 r_max). A box is its 12 triangles, exact.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "vahf/geometry/shape.h"

namespace vahf::geometry {

// A closed, consistently oriented triangle mesh in the part frame, metres.
// Triangles list vertex indices counter-clockwise seen from outside, so the
// right-hand normal (b - a) x (c - a) points out of the solid. Vertices are
// shared: every edge belongs to exactly two triangles, traversed in opposite
// directions.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::int32_t, 3>> triangles;
};

// Most segments around the axis Tessellate accepts (the tolerance is then too
// small for the part's size to be meaningful).
inline constexpr int kMaxSegmentsAround = 1 << 16;

// The segment count n above for a largest radius r_max > 0, m. Throws
// vahf::InputError when chord_tolerance is not a positive finite number or n
// would exceed kMaxSegmentsAround.
int SegmentsAround(double max_radius, double chord_tolerance);

// Tessellates a shape, chord error at most chord_tolerance (m) from the exact
// surface. Profile edges on the axis (r = 0 at both ends) bound no surface and
// give no triangles; an edge with one end on the axis gives a fan (a disc or
// cone). Throws vahf::InputError as SegmentsAround does.
TriangleMesh Tessellate(const Shape& shape, double chord_tolerance);

}  // namespace vahf::geometry
