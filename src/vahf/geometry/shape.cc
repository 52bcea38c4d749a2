#include "vahf/geometry/shape.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace vahf::geometry {
namespace {

double Cross(const ProfilePoint& o, const ProfilePoint& a, const ProfilePoint& b) {
  return (a.r - o.r) * (b.z - o.z) - (a.z - o.z) * (b.r - o.r);
}

bool OnSegment(const ProfilePoint& p, const ProfilePoint& a, const ProfilePoint& b) {
  return std::min(a.r, b.r) <= p.r && p.r <= std::max(a.r, b.r) &&
         std::min(a.z, b.z) <= p.z && p.z <= std::max(a.z, b.z);
}

int Sign(double v) { return (v > 0) - (v < 0); }

// Closed segments ab and cd share at least one point.
bool SegmentsTouch(const ProfilePoint& a, const ProfilePoint& b, const ProfilePoint& c,
                   const ProfilePoint& d) {
  const int d1 = Sign(Cross(c, d, a)), d2 = Sign(Cross(c, d, b));
  const int d3 = Sign(Cross(a, b, c)), d4 = Sign(Cross(a, b, d));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && OnSegment(a, c, d)) || (d2 == 0 && OnSegment(b, c, d)) ||
         (d3 == 0 && OnSegment(c, a, b)) || (d4 == 0 && OnSegment(d, a, b));
}

[[noreturn]] void RejectPoint(std::size_t k, const std::string& rule) {
  throw ProfileError(k, rule);
}

[[noreturn]] void RejectProfile(const std::string& rule) {
  throw ProfileError(std::nullopt, rule);
}

// Integral of a polynomial of degree <= 5 in (r, z) over a triangle, times its
// signed area: the 7-point degree-5 rule of D. A. Dunavant, "High degree
// efficient symmetrical Gaussian quadrature rules for the triangle", Int. J.
// Numer. Meth. Eng. 21 (1985) 1129-1148, Table I (p = 5).
template <typename F>
double IntegrateTriangle(const ProfilePoint& a, const ProfilePoint& b,
                         const ProfilePoint& c, F f) {
  struct Rule {
    double l1, l2, l3, w;
  };
  static constexpr double a1 = 0.059715871789770, b1 = 0.470142064105115;
  static constexpr double a2 = 0.797426985353087, b2 = 0.101286507323456;
  static constexpr double w0 = 0.225, w1 = 0.132394152788506, w2 = 0.125939180544827;
  static constexpr std::array<Rule, 7> kRule = {{{1.0 / 3, 1.0 / 3, 1.0 / 3, w0},
                                                 {a1, b1, b1, w1},
                                                 {b1, a1, b1, w1},
                                                 {b1, b1, a1, w1},
                                                 {a2, b2, b2, w2},
                                                 {b2, a2, b2, w2},
                                                 {b2, b2, a2, w2}}};
  const double area = 0.5 * Cross(a, b, c);
  double sum = 0.0;
  for (const Rule& q : kRule) {
    const double r = q.l1 * a.r + q.l2 * b.r + q.l3 * c.r;
    const double z = q.l1 * a.z + q.l2 * b.z + q.l3 * c.z;
    sum += q.w * f(r, z);
  }
  return area * sum;
}

MassProperties OfProfile(const RevolvedProfile& p) {
  // Integrals over the polygon as a fan of signed triangles from vertex 0.
  double i_r = 0, i_rz = 0, i_r3 = 0, i_rz2 = 0;
  const auto& v = p.vertices;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    i_r += IntegrateTriangle(v[0], v[k], v[k + 1], [](double r, double) { return r; });
    i_rz +=
        IntegrateTriangle(v[0], v[k], v[k + 1], [](double r, double z) { return r * z; });
    i_r3 += IntegrateTriangle(v[0], v[k], v[k + 1],
                              [](double r, double) { return r * r * r; });
    i_rz2 += IntegrateTriangle(v[0], v[k], v[k + 1],
                               [](double r, double z) { return r * z * z; });
  }
  MassProperties m;
  // Revolving about z: dV = r dtheta dr dz (theorem of Pappus-Guldinus).
  m.volume = 2 * M_PI * i_r;
  const double zc = 2 * M_PI * i_rz / m.volume;
  m.centroid = {0, 0, zc};
  const double izz = 2 * M_PI * i_r3;                        // int (x^2+y^2) dV
  const double ixx_origin = M_PI * i_r3 + 2 * M_PI * i_rz2;  // int (y^2+z^2) dV
  const double ixx = ixx_origin - m.volume * zc * zc;        // parallel axis
  m.inertia_per_density = {ixx, ixx, izz};
  for (const ProfilePoint& q : v)
    m.bounding_radius = std::max(m.bounding_radius, std::hypot(q.r, q.z));
  return m;
}

MassProperties OfBox(const Box& b) {
  MassProperties m;
  const Eigen::Vector3d& s = b.size;
  m.volume = s.x() * s.y() * s.z();
  m.inertia_per_density =
      m.volume / 12.0 *
      Eigen::Vector3d(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                      s.x() * s.x() + s.y() * s.y());
  m.bounding_radius = 0.5 * s.norm();
  return m;
}

}  // namespace

RevolvedProfile MakeRevolvedProfile(const std::vector<ProfilePoint>& pts) {
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (!std::isfinite(pts[k].r) || !std::isfinite(pts[k].z))
      RejectPoint(k, "coordinates must be finite numbers");
    if (pts[k].r < 0)
      RejectPoint(k, fmt::format("r = {} is negative; a profile lies in the "
                                 "half-plane r >= 0",
                                 pts[k].r));
    if (pts[k].r > kMaxExtent || std::abs(pts[k].z) > kMaxExtent)
      RejectPoint(k, fmt::format("({}, {}) m lies beyond {} m; a part's profile lies "
                                 "within r <= {} m, |z| <= {} m",
                                 pts[k].r, pts[k].z, kMaxExtent, kMaxExtent, kMaxExtent));
  }
  if (pts.size() > kMaxProfileVertices + 1)
    RejectProfile(fmt::format("{} points; at most {} vertices (and the closing repeat)",
                              pts.size(), kMaxProfileVertices));
  if (pts.size() < 4)
    RejectProfile(
        fmt::format("{} points; a closed profile needs at least 3 distinct "
                    "vertices and its first point repeated at the end",
                    pts.size()));
  const ProfilePoint& first = pts.front();
  const ProfilePoint& last = pts.back();
  if (first.r != last.r || first.z != last.z)
    RejectProfile(
        fmt::format("open, its last point ({}, {}) is not its first ({}, "
                    "{}); repeat the first point to close it",
                    last.r, last.z, first.r, first.z));
  RevolvedProfile p;
  p.vertices.assign(pts.begin(), pts.end() - 1);
  const auto& v = p.vertices;
  const std::size_t n = v.size();
  for (std::size_t k = 0; k < n; ++k) {
    const ProfilePoint& a = v[k];
    const ProfilePoint& b = v[(k + 1) % n];
    if (a.r == b.r && a.z == b.z)
      RejectPoint((k + 1) % n == 0 ? n : k + 1,
                  "repeats the point before it (zero-length edge)");
  }
  for (std::size_t i = 0; i < n; ++i) {
    const ProfilePoint& a = v[i];
    const ProfilePoint& b = v[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const ProfilePoint& c = v[j];
      const ProfilePoint& d = v[(j + 1) % n];
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Neighbours share a vertex; they may not fold back over each other.
        const ProfilePoint& shared = j == i + 1 ? b : a;
        const ProfilePoint& p1 = j == i + 1 ? a : b;
        const ProfilePoint& p2 = j == i + 1 ? d : c;
        const double dot =
            (p1.r - shared.r) * (p2.r - shared.r) + (p1.z - shared.z) * (p2.z - shared.z);
        if (Cross(shared, p1, p2) == 0 && dot > 0)
          RejectPoint(j == i + 1 ? j : i, "the profile folds back on itself here");
        continue;
      }
      if (SegmentsTouch(a, b, c, d))
        RejectPoint(j, fmt::format("edge {}-{} crosses or touches edge {}-{}; a "
                                   "profile must be a simple (non-self-crossing) polygon",
                                   i, (i + 1) % n, j, (j + 1) % n));
    }
  }
  double twice_area = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    twice_area += v[k].r * v[(k + 1) % n].z - v[(k + 1) % n].r * v[k].z;
  if (std::abs(twice_area) < 2 * kMinProfileArea)
    RejectProfile(fmt::format("encloses {:.3g} m^2; at least {:g} m^2 (a 10 um square)",
                              std::abs(twice_area) / 2, kMinProfileArea));
  if (twice_area < 0) std::reverse(p.vertices.begin(), p.vertices.end());
  return p;
}

MassProperties ComputeMassProperties(const Shape& shape) {
  if (const auto* p = std::get_if<RevolvedProfile>(&shape)) return OfProfile(*p);
  return OfBox(std::get<Box>(shape));
}

}  // namespace vahf::geometry
