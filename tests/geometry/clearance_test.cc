// Radial clearance of coaxial solids of revolution against the fits they are
// built with: the peg scene's 50 um (bore radius 10.05 mm, peg 10 mm), a
// sleeve on a rod (the gap outside the rod), a flipped axis, and the cases
// with no fit (offset axes, tilted axes, a box, faces that do not overlap).
#include "vahf/geometry/clearance.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vahf::geometry {
namespace {

RevolvedProfile Profile(std::vector<ProfilePoint> p) {
  p.push_back(p.front());
  return MakeRevolvedProfile(p);
}

// The peg scene's bore block and peg (experiments/scenes/peg_in_hole.json).
RevolvedProfile Bore() {
  return Profile({{0.0, -0.05},
                  {0.03, -0.05},
                  {0.03, 0.0},
                  {0.01105, 0.0},
                  {0.01005, -0.001},
                  {0.01005, -0.04},
                  {0.0, -0.04}});
}
RevolvedProfile Peg() {
  return Profile({{0.0, 0.0}, {0.0095, 0.0}, {0.01, 0.0005}, {0.01, 0.05}, {0.0, 0.05}});
}

Eigen::Isometry3d At(double x, double y, double z, double tilt_rad = 0) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = Eigen::AngleAxisd(tilt_rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
  p.translation() = Eigen::Vector3d(x, y, z);
  return p;
}

TEST(RadialClearance, PegInBoreIsFiftyMicrometres) {
  const auto c = SmallestRadialClearance(Peg(), At(0, 0, 0.91), Bore(), At(0, 0, 0.95));
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(*c, 50e-6, 1e-12);
  // Symmetric in its arguments.
  EXPECT_NEAR(*SmallestRadialClearance(Bore(), At(0, 0, 0.95), Peg(), At(0, 0, 0.91)),
              50e-6, 1e-12);
}

TEST(RadialClearance, SleeveOnARodIsTheGapOutsideTheRod) {
  const RevolvedProfile rod = Profile({{0, 0}, {0.018, 0}, {0.018, 0.3}, {0, 0.3}});
  const RevolvedProfile sleeve =
      Profile({{0.018028, 0}, {0.03, 0}, {0.03, 0.04}, {0.018028, 0.04}});
  const auto c = SmallestRadialClearance(sleeve, At(0, 0, 0.2), rod, At(0, 0, 0));
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(*c, 28e-6, 1e-12);
}

TEST(RadialClearance, AFlippedAxisStillFits) {
  // The peg upside down (rotated 180 deg about x), its span mapped onto the bore's.
  const auto c =
      SmallestRadialClearance(Peg(), At(0, 0, 0.96, M_PI), Bore(), At(0, 0, 0.95));
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(*c, 50e-6, 1e-12);
}

TEST(RadialClearance, NoFitWhenNotCoaxialOrNotOverlapping) {
  EXPECT_FALSE(SmallestRadialClearance(Peg(), At(1e-5, 0, 0.91), Bore(), At(0, 0, 0.95)));
  EXPECT_FALSE(
      SmallestRadialClearance(Peg(), At(0, 0, 0.91, 0.01), Bore(), At(0, 0, 0.95)));
  EXPECT_FALSE(SmallestRadialClearance(Peg(), At(0, 0, 1.5), Bore(), At(0, 0, 0.95)));
  EXPECT_FALSE(
      SmallestRadialClearance(Box{{0.1, 0.1, 0.1}}, At(0, 0, 0), Bore(), At(0, 0, 0)));
}

}  // namespace
}  // namespace vahf::geometry
