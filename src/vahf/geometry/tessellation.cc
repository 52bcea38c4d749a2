#include "vahf/geometry/tessellation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "vahf/core/error.h"

namespace vahf::geometry {
namespace {

using Index = std::int32_t;

TriangleMesh OfProfile(const RevolvedProfile& profile, double chord_tolerance) {
  const std::vector<ProfilePoint>& v = profile.vertices;
  const std::size_t m = v.size();
  VAHF_CHECK(m >= 3, "a profile has at least 3 vertices");
  double twice_area = 0.0, r_max = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    twice_area += v[k].r * v[(k + 1) % m].z - v[(k + 1) % m].r * v[k].z;
    r_max = std::max(r_max, v[k].r);
  }
  VAHF_CHECK(twice_area > 0.0,
             "a RevolvedProfile is counter-clockwise (MakeRevolvedProfile makes it so)");
  const int n = SegmentsAround(r_max, chord_tolerance);

  std::vector<double> cos_j(n), sin_j(n);
  for (int j = 0; j < n; ++j) {
    const double theta = 2.0 * M_PI * j / n;
    cos_j[j] = std::cos(theta);
    sin_j[j] = std::sin(theta);
  }
  // A profile vertex on the axis is one mesh vertex; any other is a ring of n,
  // ring[k] + j at angle theta_j.
  TriangleMesh mesh;
  std::vector<Index> ring(m);
  for (std::size_t k = 0; k < m; ++k) {
    ring[k] = static_cast<Index>(mesh.vertices.size());
    if (v[k].r == 0.0) {
      mesh.vertices.emplace_back(0.0, 0.0, v[k].z);
      continue;
    }
    for (int j = 0; j < n; ++j)
      mesh.vertices.emplace_back(v[k].r * cos_j[j], v[k].r * sin_j[j], v[k].z);
  }
  // Edge a -> b of a counter-clockwise profile has the solid on its left; with
  // theta increasing towards +y, (A_j, A_j+1, B_j+1) and (A_j, B_j+1, B_j) then
  // face outwards.
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t l = (k + 1) % m;
    const bool a_on_axis = v[k].r == 0.0, b_on_axis = v[l].r == 0.0;
    if (a_on_axis && b_on_axis) continue;  // inside the solid: no surface
    for (int j = 0; j < n; ++j) {
      const Index jn = (j + 1) % n;
      const Index a0 = ring[k] + (a_on_axis ? 0 : j), a1 = ring[k] + (a_on_axis ? 0 : jn);
      const Index b0 = ring[l] + (b_on_axis ? 0 : j), b1 = ring[l] + (b_on_axis ? 0 : jn);
      if (!a_on_axis) mesh.triangles.push_back({a0, a1, b1});
      if (!b_on_axis) mesh.triangles.push_back({a0, b1, b0});
    }
  }
  return mesh;
}

TriangleMesh OfBox(const Box& box) {
  VAHF_CHECK(box.size.allFinite() && (box.size.array() > 0).all(),
             "box edge lengths are positive (the scene loader checks them)");
  const Eigen::Vector3d h = 0.5 * box.size;
  TriangleMesh mesh;
  // Vertex i has x = +h.x if bit 0 of i is set, y from bit 1, z from bit 2.
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                               (i & 4) ? h.z() : -h.z());
  // Two triangles per face, counter-clockwise seen from outside.
  mesh.triangles = {{0, 2, 3}, {0, 3, 1},   // -z
                    {4, 5, 7}, {4, 7, 6},   // +z
                    {0, 1, 5}, {0, 5, 4},   // -y
                    {2, 6, 7}, {2, 7, 3},   // +y
                    {0, 4, 6}, {0, 6, 2},   // -x
                    {1, 3, 7}, {1, 7, 5}};  // +x
  return mesh;
}

void CheckTolerance(double chord_tolerance) {
  if (!std::isfinite(chord_tolerance) || chord_tolerance <= 0.0)
    throw InputError("", "tessellation chord tolerance",
                     fmt::format("{}", chord_tolerance),
                     "must be a positive length in metres");
}

}  // namespace

int SegmentsAround(double max_radius, double chord_tolerance) {
  CheckTolerance(chord_tolerance);
  VAHF_CHECK(std::isfinite(max_radius) && max_radius > 0.0,
             "a solid of revolution has a positive largest radius");
  const double x = 1.0 - chord_tolerance / max_radius;
  if (x <= -1.0) return 3;  // any polygon is within 2 r_max of its circle
  const double needed = M_PI / std::acos(x);  // +inf when acos(x) == 0
  if (!(needed <= kMaxSegmentsAround))
    throw InputError(
        "", "tessellation chord tolerance", fmt::format("{}", chord_tolerance),
        fmt::format("too small for a part of radius {} m: it needs more than {} segments "
                    "around the axis",
                    max_radius, kMaxSegmentsAround));
  return std::max(3, static_cast<int>(std::ceil(needed)));
}

TriangleMesh Tessellate(const Shape& shape, double chord_tolerance) {
  if (const auto* p = std::get_if<RevolvedProfile>(&shape))
    return OfProfile(*p, chord_tolerance);
  CheckTolerance(chord_tolerance);  // unused by a box, but a bad value is still bad
  return OfBox(std::get<Box>(shape));
}

}  // namespace vahf::geometry
