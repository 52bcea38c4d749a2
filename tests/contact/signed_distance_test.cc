// SignedDistance against independent closed forms: hand-computed distances and
// normals (Euclidean distance to a face, a circular edge, a box edge or corner)
// for a solid cylinder, the chamfered blind bore of peg_in_hole.json and a box;
// on random points, the capped-cylinder distance as the 2-D signed distance to
// the meridian rectangle [-R, R] x [0, H] (I. Quilez, "2D distance functions",
// https://iquilezles.org/articles/distfunctions2d/, box), Penetration() (the
// contact query) against the sign of At(), and the nearest-point property: p - d n lies
// on the surface. And, bit for bit, against the queries as first written, on
// the parts of the hydraulic-cylinder and peg-in-hole scenes and on the shapes
// above.
#include "vahf/contact/signed_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "vahf/geometry/shape.h"
#include "vahf/rng/stream.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::contact {
namespace {

using geometry::Box;
using geometry::MakeRevolvedProfile;
using geometry::ProfilePoint;
using geometry::Shape;

constexpr double kTol = 1e-12;  // m, for distances of order 1e-2 m

std::vector<ProfilePoint> Closed(std::vector<ProfilePoint> p) {
  p.push_back(p.front());
  return p;
}

constexpr double kR = 0.01, kH = 0.05;  // cylinder radius and height

Shape Cylinder() {
  return MakeRevolvedProfile(Closed({{0, 0}, {kR, 0}, {kR, kH}, {0, kH}}));
}

// The "bore" part of experiments/scenes/peg_in_hole.json: a block of radius
// 30 mm from z = -50 mm to 0 with a blind hole of radius 10.05 mm down to
// z = -40 mm and a 1 mm x 45 degree chamfer at its mouth.
constexpr double kBoreOuter = 0.03, kHole = 0.01005, kFloor = -0.04, kBottom = -0.05;
Shape Bore() {
  return MakeRevolvedProfile({{0.0, -0.05},
                              {0.03, -0.05},
                              {0.03, 0.0},
                              {0.01105, 0.0},
                              {0.01005, -0.001},
                              {0.01005, -0.04},
                              {0.0, -0.04},
                              {0.0, -0.05}});
}

const Eigen::Vector3d kBoxSize(0.1, 0.2, 0.3);

// A point at radius r, azimuth phi, height z.
Eigen::Vector3d Polar(double r, double phi, double z) {
  return {r * std::cos(phi), r * std::sin(phi), z};
}
Eigen::Vector3d Radial(double phi) { return {std::cos(phi), std::sin(phi), 0}; }

std::string Str(const Eigen::Vector3d& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", v.x(), v.y(), v.z());
  return buf;
}

void ExpectDistance(const SignedDistance& f, const Eigen::Vector3d& p, double distance,
                    const Eigen::Vector3d& normal) {
  SCOPED_TRACE("point " + Str(p));
  const Distance d = f.At(p);
  EXPECT_NEAR(d.distance, distance, kTol);
  EXPECT_NEAR((d.normal - normal).norm(), 0.0, 1e-9)
      << "normal " << Str(d.normal) << ", expected " << Str(normal);
  // Exactly on the surface Penetration() is not checked: its crossing-number
  // rule is half-open, and it answers inside on surfaces facing the axis (a
  // bore's wall).
  if (distance != 0) {
    const std::optional<Distance> inside = f.Penetration(p);
    EXPECT_EQ(inside.has_value(), distance < 0);
    if (inside) {
      EXPECT_EQ(inside->distance, d.distance);
    }
  }
}

// ---------------------------------------------------------------- cylinder

TEST(SignedDistanceCylinder, OutsideRadially) {
  const SignedDistance f(Cylinder());
  for (double phi : {0.0, 0.7, 2.5, -1.9})
    ExpectDistance(f, Polar(0.015, phi, 0.02), 0.005, Radial(phi));
}

TEST(SignedDistanceCylinder, AboveAndBelowTheCaps) {
  const SignedDistance f(Cylinder());
  ExpectDistance(f, {0.003, -0.004, 0.053}, 0.003, {0, 0, 1});
  ExpectDistance(f, {-0.006, 0.002, -0.0025}, 0.0025, {0, 0, -1});
}

TEST(SignedDistanceCylinder, BeyondTheRimIsTheDistanceToTheCircularEdge) {
  const SignedDistance f(Cylinder());
  // (r, z) offset (3, 4) mm from the rim (R, H): 5 mm, normal (0.6, 0.8) in (r, z).
  for (double phi : {0.3, 3.0}) {
    ExpectDistance(f, Polar(kR + 0.003, phi, kH + 0.004), 0.005,
                   0.6 * Radial(phi) + Eigen::Vector3d(0, 0, 0.8));
    // And the bottom rim, offset (4, -3) mm.
    ExpectDistance(f, Polar(kR + 0.004, phi, -0.003), 0.005,
                   0.8 * Radial(phi) + Eigen::Vector3d(0, 0, -0.6));
  }
}

TEST(SignedDistanceCylinder, InsideIsNegative) {
  const SignedDistance f(Cylinder());
  ExpectDistance(f, Polar(0.009, 1.1, 0.025), -0.001, Radial(1.1));    // near the side
  ExpectDistance(f, Polar(0.002, -0.4, 0.0485), -0.0015, {0, 0, 1});   // near the top
  ExpectDistance(f, Polar(0.0045, 2.0, 0.0007), -0.0007, {0, 0, -1});  // near the bottom
}

TEST(SignedDistanceCylinder, OnTheAxis) {
  const SignedDistance f(Cylinder());
  ExpectDistance(f, {0, 0, 0.048}, -0.002, {0, 0, 1});
  ExpectDistance(f, {0, 0, 0.003}, -0.003, {0, 0, -1});
  ExpectDistance(f, {0, 0, 0.06}, 0.01, {0, 0, 1});
  ExpectDistance(f, {0, 0, -0.001}, 0.001, {0, 0, -1});
  // Half-way up, every point of the side is nearest: the radial direction is
  // undefined, but the answer must be finite with a horizontal unit normal.
  const Distance d = f.At({0, 0, kH / 2});
  EXPECT_NEAR(d.distance, -kR, kTol);
  ASSERT_TRUE(std::isfinite(d.normal.x()) && std::isfinite(d.normal.y()) &&
              std::isfinite(d.normal.z()))
      << Str(d.normal);
  EXPECT_NEAR(d.normal.norm(), 1.0, 1e-12);
  EXPECT_NEAR(d.normal.z(), 0.0, 1e-12);
}

TEST(SignedDistanceCylinder, OnTheSurfaceTheNormalIsTheFaceNormal) {
  // Distance 0: no nearest-point direction, so the normal is the face's.
  const SignedDistance f(Cylinder());
  ExpectDistance(f, {kR, 0, 0.02}, 0, {1, 0, 0});
  ExpectDistance(f, {0, -kR, 0.03}, 0, {0, -1, 0});
  ExpectDistance(f, {0.003, 0.002, kH}, 0, {0, 0, 1});
  ExpectDistance(f, {-0.004, 0.001, 0}, 0, {0, 0, -1});
}

// ---------------------------------------------------------------- bore

TEST(SignedDistanceBore, InsideTheHoleIsOutsideTheSolid) {
  const SignedDistance f(Bore());
  // Nearest the wall (floor 20 mm away): the normal points into the hole.
  ExpectDistance(f, Polar(0.008, 0.9, -0.02), kHole - 0.008, -Radial(0.9));
  // Nearest the floor, on and off the axis.
  ExpectDistance(f, {0, 0, -0.039}, 0.001, {0, 0, 1});
  ExpectDistance(f, Polar(0.005, -2.2, -0.0395), 0.0005, {0, 0, 1});
  // Off the middle of the chamfer (10.55, -0.5) mm, along its outward normal
  // (-1, 1)/sqrt(2) in (r, z).
  const double s = std::sqrt(0.5), t = 0.0002;
  ExpectDistance(f, Polar(0.01055 - s * t, 0.4, -0.0005 + s * t), t,
                 -s * Radial(0.4) + Eigen::Vector3d(0, 0, s));
  // Above the mouth on the axis: the nearest surface point is the circle where
  // the chamfer meets the wall, (r, z) = (10.05, -1) mm; the point is 5 mm up.
  const Distance d = f.At({0, 0, 0.005});
  EXPECT_NEAR(d.distance, std::hypot(kHole, 0.006), kTol);
  EXPECT_FALSE(f.Penetration({0, 0, 0.005}).has_value());
}

TEST(SignedDistanceBore, OnTheSurfaceTheNormalIsTheFaceNormal) {
  const SignedDistance f(Bore());
  const double s = std::sqrt(0.5);
  ExpectDistance(f, {0, kHole, -0.02}, 0, {0, -1, 0});      // hole wall
  ExpectDistance(f, {0.004, 0, kFloor}, 0, {0, 0, 1});      // hole floor
  ExpectDistance(f, {0.01055, 0, -0.0005}, 0, {-s, 0, s});  // chamfer
  ExpectDistance(f, {-0.02, 0, 0}, 0, {0, 0, 1});           // top face
  ExpectDistance(f, {0, 0, kBottom}, 0, {0, 0, -1});        // bottom, on the axis
}

TEST(SignedDistanceBore, OutsideTheBlock) {
  const SignedDistance f(Bore());
  ExpectDistance(f, Polar(0.035, 1.3, -0.02), 0.005, Radial(1.3));
  ExpectDistance(f, Polar(0.02, 1.3, 0.004), 0.004, {0, 0, 1});
  ExpectDistance(f, Polar(0.0, 0.0, kBottom - 0.002), 0.002, {0, 0, -1});
}

TEST(SignedDistanceBore, InTheWallIsNegative) {
  const SignedDistance f(Bore());
  // 1.95 mm from the hole wall, 18 mm from the outside, 20 mm from the top.
  ExpectDistance(f, Polar(0.012, -0.6, -0.02), -(0.012 - kHole), -Radial(-0.6));
  // Near the outside wall.
  ExpectDistance(f, Polar(0.029, 2.8, -0.03), -0.001, Radial(2.8));
  // Near the top face, away from the chamfer.
  ExpectDistance(f, Polar(0.02, 2.8, -0.0015), -0.0015, {0, 0, 1});
}

TEST(SignedDistanceBore, TheAxisUnderTheFloorIsNotASurface) {
  // The profile's edge (0, -40 mm) - (0, -50 mm) lies on the axis: in 3-D it is
  // inside the solid. A point just under the hole floor on the axis is 0.1 mm
  // from the floor, not 0 from the axis.
  const SignedDistance f(Bore());
  ExpectDistance(f, {0, 0, kFloor - 0.0001}, -0.0001, {0, 0, 1});
  ExpectDistance(f, {0, 0, kFloor - 0.002}, -0.002, {0, 0, 1});
  ExpectDistance(f, {0, 0, kBottom + 0.003}, -0.003, {0, 0, -1});
  ExpectDistance(f, Polar(0.0005, 0.2, kFloor - 0.0003), -0.0003, {0, 0, 1});
}

// ---------------------------------------------------------------- box

TEST(SignedDistanceBox, InsideIsTheNearestFace) {
  const SignedDistance f(Box{kBoxSize});  // half extents (0.05, 0.1, 0.15)
  ExpectDistance(f, {0.01, 0.02, 0.14}, -0.01, {0, 0, 1});
  ExpectDistance(f, {-0.045, 0.0, 0.0}, -0.005, {-1, 0, 0});
  ExpectDistance(f, {0.0, -0.097, 0.1}, -0.003, {0, -1, 0});
  const Distance centre = f.At({0, 0, 0});
  EXPECT_NEAR(centre.distance, -0.05, kTol);
  EXPECT_NEAR(std::abs(centre.normal.x()), 1.0, 1e-15);
}

TEST(SignedDistanceBox, OutsideFaceEdgeAndCorner) {
  const SignedDistance f(Box{kBoxSize});
  ExpectDistance(f, {0.07, 0.05, 0.0}, 0.02, {1, 0, 0});
  ExpectDistance(f, {0.01, 0.03, -0.16}, 0.01, {0, 0, -1});
  // Beyond the edge x = 0.05, y = -0.1: offsets (3, -4) cm.
  ExpectDistance(f, {0.08, -0.14, 0.0}, 0.05, {0.6, -0.8, 0});
  // Beyond the corner (-0.05, 0.1, 0.15): offsets (-2, 3, 6) cm, 7 cm.
  ExpectDistance(f, {-0.07, 0.13, 0.21}, 0.07, Eigen::Vector3d(-2, 3, 6) / 7);
}

// ---------------------------------------------------------------- random points

struct Case {
  const char* name;
  Shape shape;
};

std::vector<Case> Shapes() {
  return {{"cylinder", Cylinder()},
          {"bore", Bore()},
          {"box", Box{kBoxSize}},
          {"cone", MakeRevolvedProfile(Closed({{0, 0}, {0.04, 0}, {0, 0.12}}))},
          {"tube", MakeRevolvedProfile(
                       Closed({{0.02, 0}, {0.03, 0}, {0.03, 0.1}, {0.02, 0.1}}))}};
}

// Uniform points in the shape's bounds grown by 20% each way; a quarter of
// them are put on the axis (x = y = 0), where the radial direction is undefined.
template <typename F>
void ForRandomPoints(const SignedDistance& f, std::uint64_t trial, F check) {
  rng::Stream s({20240607, trial}, 0, rng::Purpose::kTest);
  const Eigen::Vector3d mid = 0.5 * (f.lower() + f.upper());
  const Eigen::Vector3d span = 1.4 * (f.upper() - f.lower());
  for (int i = 0; i < 4000; ++i) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = mid[k] + (s.Uniform() - 0.5) * span[k];
    if (i % 4 == 0) p.x() = p.y() = 0;
    check(p);
  }
}

TEST(SignedDistanceRandom, PenetrationAgreesWithTheSignOfAt) {
  std::uint64_t trial = 0;
  for (const Case& c : Shapes()) {
    const SignedDistance f(c.shape);
    int inside = 0;
    ForRandomPoints(f, trial++, [&](const Eigen::Vector3d& p) {
      const Distance d = f.At(p);
      ASSERT_EQ(f.Penetration(p).has_value(), d.distance < 0)
          << c.name << " at " << Str(p) << ": distance " << d.distance;
      inside += d.distance < 0;
    });
    // Both signs were exercised.
    EXPECT_GT(inside, 200) << c.name;
    EXPECT_LT(inside, 3800) << c.name;
  }
}

TEST(SignedDistanceRandom, NormalIsUnitAndPointsToTheNearestSurfacePoint) {
  std::uint64_t trial = 100;
  for (const Case& c : Shapes()) {
    const SignedDistance f(c.shape);
    ForRandomPoints(f, trial++, [&](const Eigen::Vector3d& p) {
      const Distance d = f.At(p);
      ASSERT_NEAR(d.normal.norm(), 1.0, 1e-12) << c.name << " at " << Str(p);
      // The nearest surface point is p - d n, and it is on the surface.
      const Eigen::Vector3d foot = p - d.distance * d.normal;
      ASSERT_NEAR(f.At(foot).distance, 0.0, kTol)
          << c.name << " at " << Str(p) << ": distance " << d.distance << ", normal "
          << Str(d.normal);
    });
  }
}

TEST(SignedDistanceRandom, CylinderMatchesTheMeridianRectangle) {
  const SignedDistance f(Cylinder());
  ForRandomPoints(f, 200, [&](const Eigen::Vector3d& p) {
    const double qr = std::hypot(p.x(), p.y()) - kR;
    const double qz = std::abs(p.z() - kH / 2) - kH / 2;
    const double exact = std::min(std::max(qr, qz), 0.0) +
                         std::hypot(std::max(qr, 0.0), std::max(qz, 0.0));
    ASSERT_NEAR(f.At(p).distance, exact, kTol) << "at " << Str(p);
  });
}

TEST(SignedDistanceRandom, BoxMatchesTheClosedForm) {
  const SignedDistance f(Box{kBoxSize});
  const Eigen::Vector3d h = 0.5 * kBoxSize;
  ForRandomPoints(f, 300, [&](const Eigen::Vector3d& p) {
    // Outside: distance to the clamped point; inside: minus the distance to the
    // nearest face.
    const Eigen::Vector3d nearest = p.cwiseMax(-h).cwiseMin(h);
    const double inner = (h - p.cwiseAbs()).minCoeff();
    const double exact = inner > 0 ? -inner : (p - nearest).norm();
    ASSERT_NEAR(f.At(p).distance, exact, kTol) << "at " << Str(p);
  });
}

// ---------------------------------------------------------------- bounds

TEST(SignedDistanceBounds, AreTheSolidsBoundingBox) {
  auto expect = [](const Shape& shape, const Eigen::Vector3d& lo,
                   const Eigen::Vector3d& hi) {
    const SignedDistance f(shape);
    EXPECT_EQ(f.lower(), lo) << Str(f.lower());
    EXPECT_EQ(f.upper(), hi) << Str(f.upper());
  };
  expect(Cylinder(), {-kR, -kR, 0}, {kR, kR, kH});
  expect(Bore(), {-kBoreOuter, -kBoreOuter, kBottom}, {kBoreOuter, kBoreOuter, 0});
  expect(Box{kBoxSize}, -0.5 * kBoxSize, 0.5 * kBoxSize);
  expect(MakeRevolvedProfile(Closed({{0.02, -0.01}, {0.03, -0.01}, {0.03, 0.1}})),
         {-0.03, -0.03, -0.01}, {0.03, 0.03, 0.1});
  // Points just outside the bounds are never inside.
  const SignedDistance f(Cylinder());
  EXPECT_TRUE(f.Penetration({0, 0, 1e-9}).has_value());
  EXPECT_FALSE(f.Penetration({0, 0, -1e-9}).has_value());
  EXPECT_FALSE(f.Penetration({0, 0, kH + 1e-9}).has_value());
  EXPECT_FALSE(f.Penetration({kR + 1e-9, 0, kH / 2}).has_value());
}

// The work a query reports (a trial's contact test budget counts it): the
// edges of the point's slab that the crossing test examines and, for a point
// inside, every surface edge of the distance pass; none for a point outside
// the bounds or a box. The answer is the same with or without the count.
TEST(SignedDistanceWork, PenetrationCountsTheEdgesItExamines) {
  const SignedDistance f(Cylinder());  // 3 surface edges; 1 (the side) spans a height
  auto edges = [](const SignedDistance& field, const Eigen::Vector3d& p) {
    std::uint64_t n = 0;
    const std::optional<Distance> counted = field.Penetration(p, &n);
    const std::optional<Distance> plain = field.Penetration(p);
    EXPECT_EQ(counted.has_value(), plain.has_value());
    if (counted && plain) {
      EXPECT_EQ(counted->distance, plain->distance);
    }
    return n;
  };
  EXPECT_EQ(edges(f, {0.005, 0, 0.025}), 4u);      // inside: 1 crossing + 3 edges
  EXPECT_EQ(edges(f, {0.009, 0.009, 0.025}), 1u);  // in the bounds, outside: 1
  EXPECT_EQ(edges(f, {0, 0, kH + 1e-3}), 0u);      // beyond the bounds: none
  EXPECT_EQ(edges(SignedDistance(Box{kBoxSize}), {0, 0, 0}), 0u);
  // A sawtooth side of n teeth: the distance pass examines every one of them.
  std::vector<ProfilePoint> saw = {{0, 0}, {kR, 0}};
  const int n = 200;
  for (int i = 1; i < n; ++i) saw.push_back({kR + 0.0005 * (i % 2), kH * i / n});
  saw.push_back({kR, kH});
  saw.push_back({0, kH});
  const SignedDistance teeth(MakeRevolvedProfile(Closed(saw)));
  const std::uint64_t inside = edges(teeth, {0.005, 0, 0.0251});
  EXPECT_GE(inside, static_cast<std::uint64_t>(n));
  EXPECT_LT(edges(teeth, {0.0109, 0.0109, 0.0251}), 4u);  // outside: its slab's edge only
}

// ---------------------------------------------------------------- the first
// implementation

// The queries as first written, with scalars in the same operations and the
// same order: a crossing number over every surface edge and the nearest of all
// surface edges by clamped projection. Every contact force is summed from these
// values, so a faster SignedDistance must return the same bits, or an
// experiment's results digest changes.
class FirstImplementation {
 public:
  // The bounds are the tested field's (SignedDistanceBounds checks them).
  FirstImplementation(const Shape& shape, const SignedDistance& field)
      : lower_(field.lower()), upper_(field.upper()) {
    if (const auto* box = std::get_if<Box>(&shape)) {
      box_ = true;
      for (int k = 0; k < 3; ++k) half_[k] = 0.5 * box->size[k];
      return;
    }
    const auto& v = std::get<geometry::RevolvedProfile>(shape).vertices;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const ProfilePoint a = v[k], b = v[(k + 1) % v.size()];
      if (a.r == 0.0 && b.r == 0.0) continue;
      const double dr = b.r - a.r, dz = b.z - a.z;
      const double length = std::sqrt(dr * dr + dz * dz);
      edges_.push_back({a, b, dz / length, -(dr / length)});
    }
  }

  Distance At(const Eigen::Vector3d& p) const {
    if (box_) return OfBox(p);
    const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    return OfRevolution(p, r, Inside(r, p.z()));
  }

  std::optional<Distance> Penetration(const Eigen::Vector3d& p) const {
    for (int k = 0; k < 3; ++k)
      if (!(p[k] > lower_[k] && p[k] < upper_[k])) return std::nullopt;
    if (box_) return OfBox(p);
    const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    if (!Inside(r, p.z())) return std::nullopt;
    return OfRevolution(p, r, true);
  }

 private:
  struct Edge {
    ProfilePoint a, b;
    double out_r, out_z;
  };

  bool Inside(double r, double z) const {
    bool inside = false;
    for (const Edge& e : edges_) {
      if ((e.a.z > z) == (e.b.z > z)) continue;
      const double r_cross = e.a.r + (z - e.a.z) / (e.b.z - e.a.z) * (e.b.r - e.a.r);
      if (r < r_cross) inside = !inside;
    }
    return inside;
  }

  Distance OfRevolution(const Eigen::Vector3d& p, double r, bool inside) const {
    double best = std::numeric_limits<double>::infinity();
    double near_r = r, near_z = p.z(), n_r = 1, n_z = 0;
    for (const Edge& e : edges_) {
      const double ab_r = e.b.r - e.a.r, ab_z = e.b.z - e.a.z;
      const double t = std::clamp(
          ((r - e.a.r) * ab_r + (p.z() - e.a.z) * ab_z) / (ab_r * ab_r + ab_z * ab_z),
          0.0, 1.0);
      const double c_r = e.a.r + t * ab_r, c_z = e.a.z + t * ab_z;
      const double d2 = (r - c_r) * (r - c_r) + (p.z() - c_z) * (p.z() - c_z);
      if (d2 < best) best = d2, near_r = c_r, near_z = c_z, n_r = e.out_r, n_z = e.out_z;
    }
    const double d = std::sqrt(best);
    if (d > 1e-12) {
      n_r = (inside ? near_r - r : r - near_r) / d;
      n_z = (inside ? near_z - p.z() : p.z() - near_z) / d;
    }
    const double cos_phi = r > 0 ? p.x() / r : 1.0, sin_phi = r > 0 ? p.y() / r : 0.0;
    return {inside ? -d : d, Eigen::Vector3d(n_r * cos_phi, n_r * sin_phi, n_z)};
  }

  Distance OfBox(const Eigen::Vector3d& p) const {
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = std::abs(p[k]) - half_[k];
    if (q[0] > 0 || q[1] > 0 || q[2] > 0) {
      Eigen::Vector3d n;
      for (int k = 0; k < 3; ++k) {
        const double sign = p[k] > 0 ? 1.0 : p[k] < 0 ? -1.0 : 0.0;
        n[k] = std::max(q[k], 0.0) * sign;
      }
      const double d = std::sqrt(n.x() * n.x() + n.y() * n.y() + n.z() * n.z());
      return {d, Eigen::Vector3d(n.x() / d, n.y() / d, n.z() / d)};
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (q[k] > q[axis]) axis = k;
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    n[axis] = p[axis] >= 0 ? 1.0 : -1.0;
    return {q[axis], n};
  }

  bool box_ = false;
  double half_[3] = {0, 0, 0};
  Eigen::Vector3d lower_, upper_;
  std::vector<Edge> edges_;
};

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Empty when the two answers are the same bits, else what differs.
std::string Differs(const Distance& got, const Distance& want) {
  if (SameBits(got.distance, want.distance) &&
      SameBits(got.normal.x(), want.normal.x()) &&
      SameBits(got.normal.y(), want.normal.y()) &&
      SameBits(got.normal.z(), want.normal.z()))
    return "";
  char buf[160];
  std::snprintf(buf, sizeof buf, "distance %.17g, expected %.17g; normal ", got.distance,
                want.distance);
  return buf + Str(got.normal) + ", expected " + Str(want.normal);
}

// Points around and inside a profile: uniform in its bounds grown by 20% (an
// eighth of them on the axis); at every vertex height exactly, off and on the
// axis; at every vertex and within a few units in the last place of it; and
// across every edge, from 100 micrometres deep to 100 micrometres out and
// within a few units in the last place of it.
std::vector<Eigen::Vector3d> ProbePoints(const Shape& shape, std::uint64_t trial) {
  rng::Stream s({20240611, trial}, 0, rng::Purpose::kTest);
  const SignedDistance f(shape);
  const Eigen::Vector3d mid = 0.5 * (f.lower() + f.upper());
  const Eigen::Vector3d span = 1.4 * (f.upper() - f.lower());
  const auto azimuth = [&s] { return (s.Uniform() - 0.5) * 7.0; };
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = mid[k] + (s.Uniform() - 0.5) * span[k];
    if (i % 8 == 0) p.x() = p.y() = 0;
    points.push_back(p);
  }
  const auto* profile = std::get_if<geometry::RevolvedProfile>(&shape);
  if (!profile) {  // a box: its faces, edges and corners and just off them
    for (int i = 0; i < 20000; ++i) {
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) {
        const double u = s.Uniform();
        p[k] = u < 0.3   ? f.lower()[k]
               : u < 0.6 ? f.upper()[k]
                         : mid[k] + (s.Uniform() - 0.5) * span[k];
        if (s.Uniform() < 0.2)
          p[k] = std::nextafter(p[k], s.Uniform() < 0.5 ? -1.0 : 1.0);
      }
      points.push_back(p);
    }
    return points;
  }
  const std::vector<ProfilePoint>& v = profile->vertices;
  const double tiny[] = {0.0, 1e-300, 1e-17, 1e-15, 1e-13, 1e-12, 1e-11};
  for (std::size_t k = 0; k < v.size(); ++k) {
    const ProfilePoint a = v[k], b = v[(k + 1) % v.size()];
    for (int i = 0; i < 200; ++i) {
      points.push_back(Polar(s.Uniform() * 1.2 * f.upper().x(), azimuth(), a.z));
      points.push_back(Polar(a.r, i == 0 ? 0.0 : azimuth(), a.z));
      double r = a.r, z = a.z;
      for (int ulps = i % 4; ulps > 0; --ulps) {
        r = std::nextafter(r, s.Uniform() < 0.5 ? -1.0 : 1.0);
        z = std::nextafter(z, s.Uniform() < 0.5 ? -1.0 : 1.0);
      }
      points.push_back(Polar(std::abs(r), azimuth(), z));
    }
    points.push_back({0, 0, a.z});
    points.push_back({0, 0, std::nextafter(a.z, -1.0)});
    points.push_back({0, 0, std::nextafter(a.z, 1.0)});
    const double dr = b.r - a.r, dz = b.z - a.z, length = std::hypot(dr, dz);
    for (int i = 0; i < 2000; ++i) {
      const double t = s.Uniform(), sign = s.Uniform() < 0.5 ? -1.0 : 1.0;
      const double depth =
          i % 2 ? (s.Uniform() - 0.5) * 2e-4 : sign * tiny[i / 2 % std::size(tiny)];
      // Along the outward normal (dz, -dr) / length of a counter-clockwise edge.
      const double r = a.r + t * dr + depth * dz / length,
                   z = a.z + t * dz - depth * dr / length;
      points.push_back(Polar(std::abs(r), azimuth(), z));
    }
  }
  return points;
}

TEST(SignedDistanceFirstImplementation, SameBitsOnTheSceneParts) {
  const auto scene_shapes = [](const char* file) {
    std::vector<std::pair<std::string, Shape>> shapes;
    for (const scene::Part& part :
         scene::LoadScene(std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/" + file)
             .parts)
      shapes.emplace_back(file + (": " + part.name), part.shape);
    return shapes;
  };
  std::vector<std::pair<std::string, Shape>> shapes =
      scene_shapes("hydraulic_cylinder.json");
  for (auto& s : scene_shapes("peg_in_hole.json")) shapes.push_back(std::move(s));
  for (Case& c : Shapes()) shapes.emplace_back(c.name, std::move(c.shape));
  ASSERT_EQ(shapes.size(), 11u);
  std::uint64_t trial = 0;
  for (const auto& [name, shape] : shapes) {
    const SignedDistance f(shape);
    const FirstImplementation first(shape, f);
    int compared = 0, inside = 0, failures = 0;
    for (const Eigen::Vector3d& p : ProbePoints(shape, trial++)) {
      SCOPED_TRACE(name + " at " + Str(p));
      const std::string at = Differs(f.At(p), first.At(p));
      const std::optional<Distance> got = f.Penetration(p), want = first.Penetration(p);
      std::string penetration;
      if (got.has_value() != want.has_value())
        penetration = got ? "inside, expected outside" : "outside, expected inside";
      else if (got)
        penetration = Differs(*got, *want);
      EXPECT_EQ(at, "") << "At";
      EXPECT_EQ(penetration, "") << "Penetration";
      ++compared;
      inside += want.has_value();
      if (!at.empty() || !penetration.empty()) {
        ASSERT_LT(++failures, 10);
      }
    }
    // Both answers of Penetration were exercised.
    EXPECT_GT(inside, compared / 20) << name;
    EXPECT_LT(inside, compared - compared / 20) << name;
  }
}

// Near the barrel's bore wall, where the piston rod's shell points sit during
// the insertion: radius within 50 micrometres of 31.5115 mm (the band of
// bench/signed_distance_benchmark.cc), z along the bore and at its ends.
TEST(SignedDistanceFirstImplementation, SameBitsAtTheBarrelsBoreWall) {
  const Shape barrel = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                        "/experiments/scenes/hydraulic_cylinder.json")
                           .parts.at(0)
                           .shape;
  const SignedDistance f(barrel);
  const FirstImplementation first(barrel, f);
  rng::Stream s({20240611, 1000}, 0, rng::Purpose::kTest);
  for (int i = 0; i < 50000; ++i) {
    const double z = i % 100 == 0 ? (i % 200 ? 0.01 : 0.299) : 0.005 + s.Uniform() * 0.3;
    const Eigen::Vector3d p =
        Polar(0.0315115 + (s.Uniform() - 0.5) * 1e-4, (s.Uniform() - 0.5) * 7.0, z);
    SCOPED_TRACE("at " + Str(p));
    ASSERT_EQ(Differs(f.At(p), first.At(p)), "");
    const std::optional<Distance> got = f.Penetration(p), want = first.Penetration(p);
    ASSERT_EQ(got.has_value(), want.has_value());
    if (got) {
      ASSERT_EQ(Differs(*got, *want), "");
    }
  }
}

// FartherThan is At(p).distance > radius, to the bit, for every radius the
// broad phase could ask: zero, the distance itself and its neighbours in the
// last place (where the shortcut's rounding margin matters), and random ones.
TEST(SignedDistanceFarther, SameAnswerAsTheDistance) {
  std::vector<Shape> shapes;
  for (const scene::Part& part :
       scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                        "/experiments/scenes/hydraulic_cylinder.json")
           .parts)
    shapes.push_back(part.shape);
  for (Case& c : Shapes()) shapes.push_back(std::move(c.shape));
  rng::Stream s({20240611, 2000}, 0, rng::Purpose::kTest);
  std::uint64_t trial = 100, asked = 0, clear = 0;
  for (const Shape& shape : shapes) {
    const SignedDistance f(shape);
    for (const Eigen::Vector3d& p : ProbePoints(shape, trial++)) {
      const double d = f.At(p).distance;
      const double inf = std::numeric_limits<double>::infinity();
      for (const double radius :
           {0.0, std::abs(d), std::nextafter(std::abs(d), inf),
            std::nextafter(std::abs(d), 0.0), std::abs(d) * (1 + 1e-13),
            s.Uniform() * 1e-2, s.Uniform() * 1e-4}) {
        ASSERT_EQ(f.FartherThan(p, radius), d > radius)
            << Str(p) << " radius " << radius << " distance " << d;
        ++asked;
        clear += d > radius;
      }
    }
  }
  EXPECT_GT(clear, asked / 10);  // both answers exercised
  EXPECT_LT(clear, asked - asked / 10);
}

// SignedDistance::Near: from a meridian box, the distance from the edges it
// keeps is the whole profile's to the bit and of the same sign (the sign
// from the nearest point's side, not a crossing count: only within rounding
// of the surface may it differ), for random boxes from 1 um to 10 mm wide on
// every revolved shape; a box it calls clear holds no point inside; and a
// small box against one face keeps that face alone.
TEST(SignedDistanceNear, AgreesWithTheWholeProfileInsideItsBox) {
  rng::Stream s({20261126, 1}, 0, rng::Purpose::kTest);
  int kept = 0, boxes = 0, clear = 0;
  for (const Case& c : Shapes()) {
    if (std::holds_alternative<Box>(c.shape)) continue;
    const SignedDistance f(c.shape);
    const Eigen::Vector3d lo = f.lower(), hi = f.upper();
    for (int b = 0; b < 400; ++b) {
      const double r = s.Uniform() * 1.2 * hi.x(),
                   z = lo.z() + (s.Uniform() * 1.4 - 0.2) * (hi.z() - lo.z());
      const double wr = std::pow(10.0, -6 + 4 * s.Uniform()),
                   wz = std::pow(10.0, -6 + 4 * s.Uniform());
      const MeridianBox box{std::max(0.0, r - wr), r + wr, z - wz, z + wz};
      const NearEdges near = f.Near(box);
      ++boxes;
      clear += near.clear();
      if (near.count() > 0) kept += near.count();
      for (int i = 0; i < 50; ++i) {
        const double pr = box.r_min + s.Uniform() * (box.r_max - box.r_min);
        const double pz = box.z_min + s.Uniform() * (box.z_max - box.z_min);
        const Eigen::Vector3d p = Polar(pr, 2 * M_PI * s.Uniform(), pz);
        const Distance whole = f.At(p);
        if (near.clear()) {
          ASSERT_GE(whole.distance, 0.0) << c.name << " at " << Str(p);
          continue;
        }
        const Distance d = near.At(p);
        ASSERT_EQ(std::abs(d.distance), std::abs(whole.distance))
            << c.name << " at " << Str(p);
        if (std::abs(whole.distance) > 1e-15) {
          ASSERT_EQ(d.distance, whole.distance) << c.name << " at " << Str(p);
          ASSERT_NEAR((d.normal - whole.normal).norm(), 0.0, 1e-12)
              << c.name << " at " << Str(p);
        }
      }
    }
  }
  EXPECT_GT(clear, boxes / 10);  // both kinds of box exercised
  EXPECT_LT(clear, boxes - boxes / 10);
  EXPECT_LT(kept, 3 * (boxes - clear));  // a few edges a box, not all of them
  // Outside the cone's sharp rim (interior angle 72 deg) the nearest point is
  // the rim, and the point is below the bottom face's plane on one side and
  // beyond the slant's on the other: only the sum of the two normals tells
  // it is outside.
  const Shape cone = Shapes()[3].shape;
  const SignedDistance f(cone);
  const Eigen::Vector2d rim(0.04, 0), n_bottom(0, -1),
      n_slant = Eigen::Vector2d(0.12, 0.04).normalized();
  for (const double w : {0.1, 0.5, 0.9}) {
    const Eigen::Vector2d q =
        rim + 1e-3 * ((1 - w) * n_bottom + w * n_slant).normalized();
    const NearEdges near =
        f.Near({q.x() - 1e-6, q.x() + 1e-6, q.y() - 1e-6, q.y() + 1e-6});
    const Distance d = near.At(Eigen::Vector3d(q.x(), 0, q.y()));
    EXPECT_NEAR(d.distance, 1e-3, 1e-15) << "w " << w;
    EXPECT_EQ(d.distance, f.At(Eigen::Vector3d(q.x(), 0, q.y())).distance) << "w " << w;
  }
  // 10 um of the bore's wall, 20 um into the hole from it: the wall alone.
  const SignedDistance bore(Bore());
  const NearEdges wall = bore.Near({kHole - 20e-6, kHole + 5e-6, -0.02, -0.019});
  ASSERT_EQ(wall.count(), 1);
  EXPECT_EQ(wall.edge(0).a, Eigen::Vector2d(kHole, -0.001));
}

// The load's direction inside a solid (LoadNormal) at the cylinder's top
// corner (r = R, z = H), whose medial axis is r - R = z - H: on the axis the
// bisector; off it, the nearest face's normal blended in with weight
// s(t) = 3 t^2 - 2 t^3, t = 1 - (depth difference) / band; the nearest
// face's alone past the band, and with band 0; the same from the near edges
// of a box about the point (NearEdges) as from the whole profile.
TEST(SignedDistanceLoadNormal, BlendsAcrossTheMedialAxisOfACorner) {
  const SignedDistance f(Cylinder());
  const double band = 1e-6, depth = 3e-6;
  const auto at = [](double r, double z) { return Polar(r, 0.3, z); };
  const Eigen::Vector3d radial = Radial(0.3), up(0, 0, 1);
  // On the axis: the bisector.
  const Eigen::Vector3d p = at(kR - depth, kH - depth);
  EXPECT_LT((f.LoadNormal(p, f.At(p), band) - (radial + up).normalized()).norm(), 1e-9);
  for (double u : {0.1e-6, 0.4e-6, 0.8e-6}) {
    // Nearer the top by u: the side's direction weighs s(1 - u / band).
    const Eigen::Vector3d q = at(kR - depth, kH - depth + u);
    const Distance d = f.At(q);
    ASSERT_LT((d.normal - up).norm(), 1e-12);
    const double t = 1 - u / band, w = t * t * (3 - 2 * t);
    EXPECT_LT((f.LoadNormal(q, d, band) - (up + w * radial).normalized()).norm(), 1e-9)
        << u;
    const NearEdges near = f.Near({kR - 2 * depth, kR, kH - 2 * depth, kH});
    ASSERT_GE(near.count(), 0);
    EXPECT_EQ(near.LoadNormal(q, near.At(q), band), f.LoadNormal(q, d, band)) << u;
  }
  // Past the band, with band 0, and outside: the nearest face's normal.
  const Eigen::Vector3d past = at(kR - depth, kH - depth + 1.5 * band);
  EXPECT_EQ(f.LoadNormal(past, f.At(past), band), f.At(past).normal);
  EXPECT_EQ(f.LoadNormal(p, f.At(p), 0.0), f.At(p).normal);
  const Eigen::Vector3d outside = at(kR + depth, kH + depth);
  EXPECT_EQ(f.LoadNormal(outside, f.At(outside), band), f.At(outside).normal);
}

}  // namespace
}  // namespace vahf::contact
