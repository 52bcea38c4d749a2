// Tessellation of part shapes. Oracles (reference/analytic/README.md):
// - closed and consistently oriented: every directed edge (a, b) occurs once
//   and its reverse (b, a) once;
// - every vertex lies on the exact surface, and no chord strays more than the
//   tolerance from it: r (1 - cos(pi / n)) <= tol with n from the formula in
//   tessellation.h, and n is the least such count;
// - enclosed volume (divergence theorem) is exactly the exact volume times
//   n sin(2 pi / n) / (2 pi), the area ratio of a regular n-gon inscribed in a
//   circle, for every ring alike; so it converges to ComputeMassProperties'
//   volume as the tolerance shrinks.
#include "vahf/geometry/tessellation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <utility>

#include "test_shapes.h"
#include "vahf/core/error.h"

namespace vahf::geometry {
namespace {

using testing::Ball;
using testing::Revolved;

double EnclosedVolume(const TriangleMesh& mesh) {
  double six_v = 0.0;
  for (const auto& t : mesh.triangles)
    six_v += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  return six_v / 6.0;
}

// Every directed edge once, its reverse once, no degenerate triangle.
void ExpectClosedAndOriented(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      ASSERT_NE(t[e], t[(e + 1) % 3]) << "degenerate triangle";
      ++directed[{t[e], t[(e + 1) % 3]}];
    }
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    const auto reverse = directed.find({edge.second, edge.first});
    EXPECT_TRUE(reverse != directed.end() && reverse->second == 1)
        << "edge " << edge.first << "-" << edge.second << " has no opposite";
  }
}

const Shape kPeg =
    Revolved({{0, 0}, {0.0095, 0}, {0.01, 0.0005}, {0.01, 0.05}, {0, 0.05}});
const Shape kBore = Revolved({{0.0, -0.05},
                              {0.03, -0.05},
                              {0.03, 0.0},
                              {0.01105, 0.0},
                              {0.01005, -0.001},
                              {0.01005, -0.04},
                              {0.0, -0.04}});
const Shape kTube = Revolved({{0.02, 0}, {0.03, 0}, {0.03, 0.1}, {0.02, 0.1}});
const Shape kCone = Revolved({{0, 0}, {0.04, 0}, {0, 0.12}});

TEST(SegmentsAround, LeastCountMeetingTheTolerance) {
  EXPECT_EQ(SegmentsAround(0.01, 1e-4), 23);  // pi / acos(0.99) = 22.2
  EXPECT_EQ(SegmentsAround(0.01, 0.02), 3);   // tol >= 2 r: any triangle will do
  EXPECT_EQ(SegmentsAround(0.01, 0.009), 3);  // the floor of 3
  for (const double r : {0.003, 0.01, 0.03, 1.0}) {
    for (const double tol : {1e-3, 1e-4, 1e-5, 1e-6}) {
      const int n = SegmentsAround(r, tol);
      EXPECT_LE(r * (1 - std::cos(M_PI / n)), tol * (1 + 1e-12)) << r << " " << tol;
      if (n > 3) {
        EXPECT_GT(r * (1 - std::cos(M_PI / (n - 1))), tol) << r << " " << tol;
      }
    }
  }
}

TEST(SegmentsAround, RejectsBadTolerances) {
  for (const double tol : {0.0, -1e-4, double{NAN}, double{INFINITY}}) {
    try {
      SegmentsAround(0.01, tol);
      ADD_FAILURE() << "accepted tolerance " << tol;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("must be a positive length in metres"));
    }
  }
  try {
    Tessellate(kPeg, 1e-300);
    ADD_FAILURE() << "accepted a tolerance needing a billion segments";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("too small for a part of radius 0.01 m"));
  }
  EXPECT_THROW(Tessellate(Box{{1, 1, 1}}, -1.0), InputError);
}

TEST(Tessellate, ClosedAndOrientedOutwards) {
  for (const Shape* s : {&kPeg, &kBore, &kTube, &kCone}) {
    const TriangleMesh mesh = Tessellate(*s, 1e-4);
    ExpectClosedAndOriented(mesh);
    EXPECT_GT(EnclosedVolume(mesh), 0.0);  // outward normals
  }
  const TriangleMesh ball = Tessellate(Ball(0.02, 40), 1e-5);
  ExpectClosedAndOriented(ball);
  const TriangleMesh box = Tessellate(Box{{0.1, 0.2, 0.3}}, 1e-4);
  ExpectClosedAndOriented(box);
  EXPECT_EQ(box.vertices.size(), 8u);
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_NEAR(EnclosedVolume(box), 0.006, 1e-17);
}

TEST(Tessellate, AxisEdgesGiveNoTrianglesAndAxisEndsGiveFans) {
  // The peg: a fan at each end, two quads' worth between, nothing on the
  // axis edge (0, 0.05) -> (0, 0); one vertex per axis point, n per ring.
  const int n = SegmentsAround(0.01, 1e-4);
  const TriangleMesh mesh = Tessellate(kPeg, 1e-4);
  EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(6 * n));
  EXPECT_EQ(mesh.vertices.size(), static_cast<std::size_t>(2 + 3 * n));
  // A tube touches the axis nowhere: four quad strips.
  EXPECT_EQ(Tessellate(kTube, 1e-4).triangles.size(),
            static_cast<std::size_t>(8 * SegmentsAround(0.03, 1e-4)));
}

TEST(Tessellate, VerticesOnTheSurfaceAndChordsWithinTolerance) {
  const std::vector<ProfilePoint>& profile = std::get<RevolvedProfile>(kBore).vertices;
  for (const double tol : {1e-3, 1e-4, 1e-5}) {
    const TriangleMesh mesh = Tessellate(kBore, tol);
    for (const Eigen::Vector3d& p : mesh.vertices) {
      // On the ring of some profile vertex with the same z and radius.
      bool on_ring = false;
      for (const ProfilePoint& q : profile)
        on_ring |= q.z == p.z() && std::abs(std::hypot(p.x(), p.y()) - q.r) <= 1e-15;
      EXPECT_TRUE(on_ring) << p.transpose();
    }
    // The farthest a mesh point strays inside the surface is the middle of a
    // ring chord: |a + b| / 2 against the radius |a|.
    double worst = 0.0;
    for (const auto& t : mesh.triangles) {
      for (int e = 0; e < 3; ++e) {
        const Eigen::Vector3d& a = mesh.vertices[t[e]];
        const Eigen::Vector3d& b = mesh.vertices[t[(e + 1) % 3]];
        if (a.z() != b.z()) continue;
        const double ra = std::hypot(a.x(), a.y()), rb = std::hypot(b.x(), b.y());
        if (std::abs(ra - rb) > 1e-15) continue;  // a radial edge, exact
        const Eigen::Vector3d mid = 0.5 * (a + b);
        worst = std::max(worst, ra - std::hypot(mid.x(), mid.y()));
      }
    }
    EXPECT_LE(worst, tol * (1 + 1e-9)) << "tolerance " << tol;
    EXPECT_GT(worst, 0.5 * tol) << "tolerance " << tol << ": far finer than asked";
  }
}

TEST(Tessellate, VolumeIsTheInscribedPolygonFractionAndConverges) {
  for (const Shape* s : {&kPeg, &kBore, &kTube, &kCone}) {
    const double exact = ComputeMassProperties(*s).volume;
    const auto& profile = std::get<RevolvedProfile>(*s).vertices;
    double r_max = 0.0;
    for (const ProfilePoint& q : profile) r_max = std::max(r_max, q.r);
    double last_error = INFINITY;
    for (const double tol : {1e-3, 1e-4, 1e-5, 1e-6}) {
      const int n = SegmentsAround(r_max, tol);
      const double mesh_volume = EnclosedVolume(Tessellate(*s, tol));
      EXPECT_NEAR(mesh_volume, exact * n * std::sin(2 * M_PI / n) / (2 * M_PI),
                  1e-12 * exact);
      const double error = std::abs(mesh_volume - exact) / exact;
      EXPECT_LT(error, 2 * tol / r_max);  // (2 pi / n)^2 / 6 ~ (4 / 3) tol / r_max
      EXPECT_LT(error, last_error);
      last_error = error;
    }
  }
}

}  // namespace
}  // namespace vahf::geometry
