// MakePointShell against closed-form surface areas: the shell's total patch
// area against the lateral plus end areas of a cylinder (2 pi R H + 2 pi R^2),
// a tube (2 pi (Ro + Ri) H + 2 pi (Ro^2 - Ri^2)), a cone (slant area
// pi R sqrt(R^2 + H^2) plus base pi R^2, e.g. CRC Standard Mathematical Tables,
// "Right circular cone") and a box (2 (ab + bc + ca)), at several spacings;
// each point against the same shape's SignedDistance (on the surface, normal
// pointing out), and against the centroid for convex solids.
#include "vahf/contact/point_shell.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "vahf/contact/signed_distance.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {
namespace {

using geometry::Box;
using geometry::MakeRevolvedProfile;
using geometry::ProfilePoint;
using geometry::Shape;

std::vector<ProfilePoint> Closed(std::vector<ProfilePoint> p) {
  p.push_back(p.front());
  return p;
}

constexpr double kSpacings[] = {0.004, 0.002, 0.001};

struct Case {
  const char* name;
  Shape shape;
  double area;  // exact surface area, m^2
  bool convex;
};

std::vector<Case> Cases() {
  const double r = 0.01, h = 0.05;                // cylinder
  const double ri = 0.02, ro = 0.03, ht = 0.1;    // tube
  const double rc = 0.04, hc = 0.12;              // cone
  const Eigen::Vector3d b(0.0405, 0.03, 0.0173);  // box, not a multiple of s
  return {
      {"cylinder", MakeRevolvedProfile(Closed({{0, 0}, {r, 0}, {r, h}, {0, h}})),
       2 * M_PI * r * h + 2 * M_PI * r * r, true},
      {"tube", MakeRevolvedProfile(Closed({{ri, 0}, {ro, 0}, {ro, ht}, {ri, ht}})),
       2 * M_PI * (ro + ri) * ht + 2 * M_PI * (ro * ro - ri * ri), false},
      {"cone", MakeRevolvedProfile(Closed({{0, 0}, {rc, 0}, {0, hc}})),
       M_PI * rc * std::sqrt(rc * rc + hc * hc) + M_PI * rc * rc, true},
      {"box", Box{b}, 2 * (b.x() * b.y() + b.y() * b.z() + b.z() * b.x()), true},
  };
}

TEST(PointShell, TotalAreaIsExactAtEverySpacing) {
  for (const Case& c : Cases()) {
    for (double s : kSpacings) {
      const auto shell = MakePointShell(c.shape, s);
      double area = 0;
      for (const ShellPoint& p : shell) area += p.area;
      EXPECT_NEAR(area / c.area, 1.0, 1e-12)
          << c.name << " at spacing " << s << ": " << shell.size() << " points";
    }
  }
}

TEST(PointShell, PatchesAreNoLargerThanTheSpacingSquared) {
  for (const Case& c : Cases()) {
    for (double s : kSpacings) {
      for (const ShellPoint& p : MakePointShell(c.shape, s)) {
        ASSERT_GT(p.area, 0.0) << c.name;
        ASSERT_LE(p.area, s * s * (1 + 1e-12)) << c.name << " at spacing " << s;
      }
    }
  }
}

TEST(PointShell, PointsLieOnTheSurfaceWithUnitOutwardNormals) {
  for (const Case& c : Cases()) {
    const SignedDistance f(c.shape);
    for (double s : kSpacings) {
      for (const ShellPoint& p : MakePointShell(c.shape, s)) {
        const Eigen::Vector3d& x = p.position;
        SCOPED_TRACE(::testing::Message()
                     << c.name << " at spacing " << s << ", point (" << x.x() << ", "
                     << x.y() << ", " << x.z() << ")");
        ASSERT_NEAR(p.normal.norm(), 1.0, 1e-12);
        const Distance d = f.At(x);
        ASSERT_NEAR(d.distance, 0.0, 1e-12);
        // Patch centres are never on an edge: the surface normal there is the face's.
        ASSERT_NEAR((d.normal - p.normal).norm(), 0.0, 1e-12);
        // Outward: a step along the normal leaves the solid, a step back enters it.
        const double e = 1e-6;
        ASSERT_NEAR(f.At(x + e * p.normal).distance, e, 1e-12);
        ASSERT_NEAR(f.At(x - e * p.normal).distance, -e, 1e-12);
      }
    }
  }
}

TEST(PointShell, ConvexSolidsHaveNormalsAwayFromTheCentroid) {
  for (const Case& c : Cases()) {
    if (!c.convex) continue;
    const Eigen::Vector3d centroid = geometry::ComputeMassProperties(c.shape).centroid;
    for (double s : kSpacings) {
      for (const ShellPoint& p : MakePointShell(c.shape, s))
        ASSERT_GT(p.normal.dot(p.position - centroid), 0.0)
            << c.name << " at spacing " << s;
    }
  }
}

// The size rule (kMaxShellPoints) is checked against this bound before any
// shell is made: it must hold every shell it stands for, and be loose by no
// more than the rounding of each band (one point a ring).
TEST(PointShell, SizeBoundHoldsTheShellAndIsTight) {
  for (const Case& c : Cases()) {
    for (double s : kSpacings) {
      const double n = static_cast<double>(MakePointShell(c.shape, s).size());
      const double bound = PointShellSizeBound(c.shape, s);
      EXPECT_GE(bound, n) << c.name << " at " << s;
      EXPECT_LE(bound, 1.1 * n + 100) << c.name << " at " << s;
    }
  }
  // A 10 m part at 10 um: counted in double, without making it or overflowing.
  const Shape huge = MakeRevolvedProfile(Closed({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  EXPECT_GT(PointShellSizeBound(huge, 1e-5), 1e12);
  EXPECT_TRUE(std::isfinite(PointShellSizeBound(huge, 1e-5)));
}

TEST(PointShell, PointCountGrowsFourfoldWhenSpacingHalves) {
  const Shape cylinder = Cases()[0].shape;
  std::size_t previous = 0;
  for (double s : {0.004, 0.002, 0.001, 0.0005}) {
    const std::size_t n = MakePointShell(cylinder, s).size();
    std::printf("cylinder shell at spacing %g m: %zu points\n", s, n);
    if (previous > 0) {
      const double ratio = static_cast<double>(n) / static_cast<double>(previous);
      EXPECT_GT(ratio, 3.5) << "spacing " << s;
      EXPECT_LT(ratio, 4.5) << "spacing " << s;
    }
    previous = n;
  }
}

}  // namespace
}  // namespace vahf::contact
