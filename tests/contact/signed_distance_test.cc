// SignedDistance against independent closed forms: hand-computed distances and
// normals (Euclidean distance to a face, a circular edge, a box edge or corner)
// for a solid cylinder, the chamfered blind bore of peg_in_hole.json and a box;
// on random points, the capped-cylinder distance as the 2-D signed distance to
// the meridian rectangle [-R, R] x [0, H] (I. Quilez, "2D distance functions",
// https://iquilezles.org/articles/distfunctions2d/, box), Penetration() (the
// contact query) against the sign of At(), and the nearest-point property: p - d n lies
// on the surface.
#include "vahf/contact/signed_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "vahf/geometry/shape.h"
#include "vahf/rng/stream.h"

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

}  // namespace
}  // namespace vahf::contact
