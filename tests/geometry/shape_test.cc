// Shapes: profile validation (closed, r >= 0, simple) and mass properties
// against closed forms for a cylinder, a tube, a cone and a box (volumes and
// moments of inertia of homogeneous solids, e.g. Meriam and Kraige,
// Engineering Mechanics: Dynamics, Table D/4).
#include "vahf/geometry/shape.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vahf::geometry {
namespace {

std::vector<ProfilePoint> Closed(std::vector<ProfilePoint> p) {
  p.push_back(p.front());
  return p;
}

void ExpectRejected(const std::vector<ProfilePoint>& points,
                    const std::string& fragment) {
  try {
    MakeRevolvedProfile(points);
    ADD_FAILURE() << "accepted a profile that should fail with '" << fragment << "'";
  } catch (const ProfileError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(RevolvedProfile, CylinderMatchesClosedForm) {
  const double r = 0.01, h = 0.05;
  const auto m = ComputeMassProperties(
      MakeRevolvedProfile(Closed({{0, 0}, {r, 0}, {r, h}, {0, h}})));
  const double v = M_PI * r * r * h;
  EXPECT_NEAR(m.volume, v, 1e-15);
  EXPECT_NEAR(m.centroid.z(), h / 2, 1e-15);
  EXPECT_NEAR(m.inertia_per_density.z(), v * r * r / 2, 1e-18);
  EXPECT_NEAR(m.inertia_per_density.x(), v * (3 * r * r + h * h) / 12, 1e-18);
  EXPECT_DOUBLE_EQ(m.inertia_per_density.x(), m.inertia_per_density.y());
  EXPECT_NEAR(m.bounding_radius, std::hypot(r, h), 1e-15);
}

TEST(RevolvedProfile, TubeAndClockwiseOrderGiveTheSame) {
  const double ri = 0.02, ro = 0.03, h = 0.1;
  const auto ccw = ComputeMassProperties(
      MakeRevolvedProfile(Closed({{ri, 0}, {ro, 0}, {ro, h}, {ri, h}})));
  const auto cw = ComputeMassProperties(
      MakeRevolvedProfile(Closed({{ri, 0}, {ri, h}, {ro, h}, {ro, 0}})));
  const double v = M_PI * (ro * ro - ri * ri) * h;
  EXPECT_NEAR(ccw.volume, v, 1e-15);
  EXPECT_NEAR(ccw.inertia_per_density.z(),
              M_PI * h * (std::pow(ro, 4) - std::pow(ri, 4)) / 2, 1e-18);
  EXPECT_NEAR(ccw.inertia_per_density.x(), v * (3 * (ro * ro + ri * ri) + h * h) / 12,
              1e-18);
  EXPECT_NEAR(cw.volume, ccw.volume, 1e-18);
  EXPECT_NEAR(cw.inertia_per_density.x(), ccw.inertia_per_density.x(), 1e-18);
}

TEST(RevolvedProfile, ConeMatchesClosedForm) {
  const double r = 0.04, h = 0.12;
  const auto m =
      ComputeMassProperties(MakeRevolvedProfile(Closed({{0, 0}, {r, 0}, {0, h}})));
  const double v = M_PI * r * r * h / 3;
  EXPECT_NEAR(m.volume, v, 1e-15);
  EXPECT_NEAR(m.centroid.z(), h / 4, 1e-15);
  EXPECT_NEAR(m.inertia_per_density.z(), 0.3 * v * r * r, 1e-18);
  EXPECT_NEAR(m.inertia_per_density.x(), v * (3 * r * r / 20 + 3 * h * h / 80), 1e-18);
}

TEST(Box, MatchesClosedForm) {
  const auto m = ComputeMassProperties(Box{{0.1, 0.2, 0.3}});
  EXPECT_NEAR(m.volume, 0.006, 1e-15);
  EXPECT_NEAR(m.inertia_per_density.x(), 0.006 * (0.04 + 0.09) / 12, 1e-18);
  EXPECT_NEAR(m.inertia_per_density.y(), 0.006 * (0.01 + 0.09) / 12, 1e-18);
  EXPECT_NEAR(m.inertia_per_density.z(), 0.006 * (0.01 + 0.04) / 12, 1e-18);
}

TEST(RevolvedProfile, RejectsBadProfiles) {
  ExpectRejected({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "open");
  ExpectRejected({{0, 0}, {1, 0}, {0, 0}}, "at least 3 distinct");
  ExpectRejected(Closed({{0, 0}, {1, 0}, {-0.5, 1}}), "point 2: r = -0.5 is negative");
  ExpectRejected(Closed({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), "crosses");  // bow-tie
  ExpectRejected(Closed({{0, 0}, {1, 0}, {1, 0}, {1, 1}}), "point 2: repeats");
  ExpectRejected(Closed({{0, 0}, {1, 0}, {2, 0}}), "folds back");
  ExpectRejected(Closed({{0, 0}, {1, NAN}, {1, 1}}),
                 "point 1: coordinates must be finite");
  // A vertex touching a non-adjacent edge is not a simple polygon either.
  ExpectRejected(Closed({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}), "touches");
}

TEST(RevolvedProfile, AcceptsEdgesOnTheAxis) {
  const RevolvedProfile p = MakeRevolvedProfile(
      Closed({{0, 0}, {0.0095, 0}, {0.01, 0.0005}, {0.01, 0.05}, {0, 0.05}}));
  EXPECT_EQ(p.vertices.size(), 5u);
}

}  // namespace
}  // namespace vahf::geometry
