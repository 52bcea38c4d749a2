// Rims: samples of a static part's convex edges.
//
// MakeRims against closed forms: the samples' total length against the sum of
// the convex edge circles' circumferences 2 pi r (or a box's 4 (a + b + c)),
// the sample counts against ceil(circumference / spacing), every sample on its
// edge; straight, concave and on-axis vertices give none.
#include "vahf/contact/rim.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "vahf/contact/signed_distance.h"
#include "vahf/geometry/shape.h"
#include "peg_in_bore.h"

namespace vahf::contact {
namespace {

using geometry::Box;
using geometry::ProfilePoint;
using geometry::Shape;
using testing::ChamferedBore;
using testing::ChamferedPeg;
using testing::Revolved;

double TotalLength(const std::vector<RimPoint>& rim) {
  double sum = 0;
  for (const RimPoint& q : rim) sum += q.length;
  return sum;
}

int Count(double length, double spacing) {
  return static_cast<int>(std::ceil(length / spacing));
}

// Every sample of `rim` lies on one of the circles (r, z), in order, each
// circle a run of Count(2 pi r, spacing) samples of length 2 pi r / count.
void ExpectCircles(const std::vector<RimPoint>& rim, double spacing,
                   const std::vector<ProfilePoint>& circles) {
  std::size_t k = 0;
  double circumferences = 0;
  for (const ProfilePoint& c : circles) {
    const double circumference = 2 * M_PI * c.r;
    circumferences += circumference;
    const int n = Count(circumference, spacing);
    ASSERT_LE(k + n, rim.size());
    for (int j = 0; j < n; ++j, ++k) {
      const RimPoint& q = rim[k];
      EXPECT_NEAR(std::hypot(q.position.x(), q.position.y()), c.r, 1e-15) << k;
      EXPECT_EQ(q.position.z(), c.z) << k;
      EXPECT_NEAR(q.length, circumference / n, 1e-18) << k;
      EXPECT_LE(q.length, spacing) << k;
    }
  }
  EXPECT_EQ(rim.size(), k);
  // Exact but for the rounding of a sum of a few hundred terms.
  EXPECT_NEAR(TotalLength(rim), circumferences, 1e-12 * circumferences);
}

// ---------------------------------------------------------------- MakeRims

TEST(MakeRims, CylinderHasItsTwoEndCircles) {
  const double r = 0.01, h = 0.05;
  for (double s : {1e-3, 0.5e-3, 0.13e-3}) {
    const auto rim = MakeRims(Revolved({{0, 0}, {r, 0}, {r, h}, {0, h}}), s);
    ExpectCircles(rim, s, {{r, 0}, {r, h}});
  }
  // 2 pi 10 mm / 0.5 mm = 125.66: 126 samples a circle.
  EXPECT_EQ(MakeRims(Revolved({{0, 0}, {r, 0}, {r, h}, {0, h}}), 0.5e-3).size(), 2u * 126);
}

TEST(MakeRims, ChamferedBoreHasFourCirclesAndNoneAtItsConcaveBottom) {
  // The peg_in_hole scene's bore block: outer bottom and top corners (90 deg),
  // the top face to chamfer and chamfer to wall circles (135 deg each); the
  // bore's bottom corner (r = 10.05 mm, z = -40 mm) is concave (270 deg) and
  // the vertices on the axis are not edges.
  const auto rim = MakeRims(ChamferedBore(), 0.5e-3);
  ExpectCircles(rim, 0.5e-3,
                {{0.03, -0.05}, {0.03, 0.0}, {0.01105, 0.0}, {0.01005, -0.001}});
  for (const RimPoint& q : rim) EXPECT_NE(q.position.z(), -0.04);
}

TEST(MakeRims, ChamferedPegHasThreeCircles) {
  const auto rim = MakeRims(ChamferedPeg(), 1e-3);
  ExpectCircles(rim, 1e-3, {{0.0095, 0}, {0.01, 0.0005}, {0.01, 0.05}});
}

TEST(MakeRims, StraightAndNearlyStraightVerticesGiveNone) {
  // The side wall split at mid height (exactly straight), and a wall bent by
  // 0.5 deg (interior angle 179.5 deg, blunter than the 179 deg limit): only
  // the two end circles. Bent by 2 deg: a third circle at the bend.
  const double r = 0.01, h = 0.04;
  const double s = 1e-3;
  const auto straight = MakeRims(Revolved({{0, 0}, {r, 0}, {r, h / 2}, {r, h}, {0, h}}), s);
  ExpectCircles(straight, s, {{r, 0}, {r, h}});
  // The upper half leans inwards by `bend`: the vertex at mid height turns left.
  const auto bent = [&](double bend_deg) {
    const double top_r = r - (h / 2) * std::tan(bend_deg * M_PI / 180);
    return MakeRims(Revolved({{0, 0}, {r, 0}, {r, h / 2}, {top_r, h}, {0, h}}), s);
  };
  const double blunt_top = r - (h / 2) * std::tan(0.5 * M_PI / 180);
  ExpectCircles(bent(0.5), s, {{r, 0}, {blunt_top, h}});
  const double sharp_top = r - (h / 2) * std::tan(2.0 * M_PI / 180);
  ExpectCircles(bent(2.0), s, {{r, 0}, {r, h / 2}, {sharp_top, h}});
}

TEST(MakeRims, ConeHasOnlyItsBaseCircle) {
  // The apex lies on the axis: no circle there.
  const auto rim = MakeRims(Revolved({{0, 0}, {0.02, 0}, {0, 0.03}}), 1e-3);
  ExpectCircles(rim, 1e-3, {{0.02, 0}});
}

TEST(MakeRims, GroovedTubeHasNoCircleAtTheGrooveBottom) {
  // A tube (inner radius 5 mm, outer 10 mm) has four convex end circles; a
  // rectangular groove cut 2 mm into its outer wall adds its two lips (convex,
  // 90 deg) but not its bottom corners (concave, 270 deg).
  const auto rim = MakeRims(Revolved({{0.005, 0},
                                      {0.01, 0},
                                      {0.01, 0.01},
                                      {0.008, 0.01},
                                      {0.008, 0.012},
                                      {0.01, 0.012},
                                      {0.01, 0.02},
                                      {0.005, 0.02}}),
                            1e-3);
  ExpectCircles(rim, 1e-3,
                {{0.005, 0}, {0.01, 0}, {0.01, 0.01}, {0.01, 0.012}, {0.01, 0.02},
                 {0.005, 0.02}});
  for (const RimPoint& q : rim)
    EXPECT_GT(std::abs(std::hypot(q.position.x(), q.position.y()) - 0.008), 1e-3);
}

TEST(MakeRims, BoxHasTwelveEdgesSampledAtSegmentMidpoints) {
  const Eigen::Vector3d size(0.04, 0.01, 0.023);
  const double s = 1e-3;
  const auto rim = MakeRims(Box{size}, s);
  // 10 mm at 1 mm is exactly 10 samples, though 0.01 / 0.001 rounds above 10.
  const int nx = 40, ny = 10, nz = 23;
  ASSERT_EQ(rim.size(), static_cast<std::size_t>(4 * (nx + ny + nz)));
  EXPECT_NEAR(TotalLength(rim), 4 * size.sum(), 1e-15);
  const SignedDistance field{Box{size}};
  for (const RimPoint& q : rim) {
    // On exactly two faces, inside the third pair, at a segment midpoint.
    int on_faces = 0, along = -1;
    for (int a = 0; a < 3; ++a) {
      if (std::abs(q.position[a]) == size[a] / 2)
        ++on_faces;
      else
        along = a;
    }
    ASSERT_EQ(on_faces, 2);
    const int n = along == 0 ? nx : along == 1 ? ny : nz;
    const double i = (q.position[along] + size[along] / 2) / q.length - 0.5;
    EXPECT_NEAR(i, std::round(i), 1e-9);
    EXPECT_NEAR(q.length, size[along] / n, 1e-18);
    EXPECT_NEAR(field.At(q.position).distance, 0.0, 1e-15);
  }
}

TEST(MakeRims, SamplesLieOnTheSurface) {
  const SignedDistance field(ChamferedBore());
  for (const RimPoint& q : MakeRims(ChamferedBore(), 0.5e-3))
    EXPECT_NEAR(field.At(q.position).distance, 0.0, 1e-15);
}

}  // namespace
}  // namespace vahf::contact
