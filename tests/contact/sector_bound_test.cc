// The meridian broad phase (sector_bound.h, SignedDistance::MeridianBoxClear)
// against brute force: the least arc of given azimuths, every point of a
// random cluster carried by a random rigid transform inside the box its bound
// gives (small tilts as in an insertion, and arbitrary turns), the box exact
// when the axes coincide, and the box-against-profile test against a dense
// grid of point queries in the box.
#include "vahf/contact/sector_bound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "peg_in_bore.h"
#include "vahf/contact/signed_distance.h"
#include "vahf/rng/stream.h"

namespace vahf::contact {
namespace {

constexpr double kDeg = M_PI / 180.0;

Eigen::Vector3d OnCylinder(double rho, double phi, double zeta) {
  return {rho * std::cos(phi), rho * std::sin(phi), zeta};
}

double Azimuth(const Eigen::Vector2d& e) { return std::atan2(e.y(), e.x()); }

TEST(BoundSector, LeastArcOfAPatch) {
  std::vector<Eigen::Vector3d> points;
  for (double phi = 30; phi <= 100; phi += 5)
    for (double zeta : {0.0, 0.002, 0.005})
      points.push_back(OnCylinder(0.01, phi * kDeg, zeta));
  const SectorBound s = BoundSector(points);
  EXPECT_NEAR(s.rho_min, 0.01, 1e-15);
  EXPECT_NEAR(s.rho_max, 0.01, 1e-15);
  EXPECT_EQ(s.zeta_min, 0.0);
  EXPECT_EQ(s.zeta_max, 0.005);
  EXPECT_NEAR(s.width, 70 * kDeg, 1e-8);
  EXPECT_NEAR(Azimuth(s.from), 30 * kDeg, 1e-8);
  EXPECT_NEAR(Azimuth(s.to), 100 * kDeg, 1e-8);
}

TEST(BoundSector, ArcAcrossTheNegativeXAxisAndFullCircles) {
  std::vector<Eigen::Vector3d> points;
  for (double phi : {170.0, 175.0, -178.0, -160.0})
    points.push_back(OnCylinder(0.02, phi * kDeg, 0));
  const SectorBound s = BoundSector(points);
  EXPECT_NEAR(s.width, 30 * kDeg, 1e-8);
  EXPECT_NEAR(Azimuth(s.from), 170 * kDeg, 1e-8);
  EXPECT_NEAR(Azimuth(s.to), -160 * kDeg, 1e-8);

  points.push_back({0, 0, 0.001});  // on the axis: every azimuth
  EXPECT_GT(BoundSector(points).width, 2 * M_PI);
  std::vector<Eigen::Vector3d> ring;  // 12 points 30 deg apart: 330 deg of arc
  for (int k = 0; k < 12; ++k) ring.push_back(OnCylinder(0.01, k * 30 * kDeg, 0));
  EXPECT_NEAR(BoundSector(ring).width, 330 * kDeg, 1e-8);
  for (int k = 0; k < 3600; ++k) ring.push_back(OnCylinder(0.01, k * 0.1 * kDeg, 0));
  EXPECT_GT(BoundSector(ring).width, 2 * M_PI);  // a gap of 0.1 deg: the whole circle
}

// A random rigid transform: a tilt of up to max_tilt about a random horizontal
// axis, a random turn about z, and a shift of up to `shift` per axis.
Eigen::Isometry3d RandomTransform(rng::Stream& s, double max_tilt, double shift) {
  const double axis = 2 * M_PI * s.Uniform();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = (Eigen::AngleAxisd(max_tilt * s.Uniform(),
                                  Eigen::Vector3d(std::cos(axis), std::sin(axis), 0)) *
                Eigen::AngleAxisd(2 * M_PI * s.Uniform(), Eigen::Vector3d::UnitZ()))
                   .toRotationMatrix();
  t.translation() = shift * Eigen::Vector3d(2 * s.Uniform() - 1, 2 * s.Uniform() - 1,
                                            2 * s.Uniform() - 1);
  return t;
}

TEST(MeridianMap, EveryPointOfTheClusterLiesInItsBox) {
  rng::Stream s({20261123, 1}, 0, rng::Purpose::kTest);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // A patch of a cylinder or cone (arc up to 360 deg), or a random cloud.
    std::vector<Eigen::Vector3d> points;
    const double phi0 = 2 * M_PI * s.Uniform(), arc = 2 * M_PI * s.Uniform();
    const double rho = 0.001 + 0.03 * s.Uniform(),
                 slope = trial % 3 == 0 ? s.Uniform() : 0.0;
    for (int k = 0; k < 24; ++k) {
      const double zeta = 0.02 * s.Uniform();
      points.push_back(trial % 5 == 4 ? Eigen::Vector3d(0.02 * s.Uniform() - 0.01,
                                                        0.02 * s.Uniform() - 0.01, zeta)
                                      : OnCylinder(rho + slope * zeta,
                                                   phi0 + arc * s.Uniform(), zeta));
    }
    const SectorBound bound = BoundSector(points);
    const Eigen::Isometry3d t =
        RandomTransform(s, trial % 2 == 0 ? 3 * kDeg : M_PI, trial % 4 == 0 ? 0.5 : 1e-4);
    const MeridianBox box = MeridianMap(t)(bound);
    for (const Eigen::Vector3d& q : points) {
      const Eigen::Vector3d p = t * q;
      const double r = std::hypot(p.x(), p.y());
      EXPECT_GE(r, box.r_min) << trial;
      EXPECT_LE(r, box.r_max) << trial;
      EXPECT_GE(p.z(), box.z_min) << trial;
      EXPECT_LE(p.z(), box.z_max) << trial;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 400 * 24);
}

TEST(MeridianMap, ExactWhenTheAxesCoincide) {
  // Turned about the common axis and shifted along it: r is rho, z is zeta
  // plus the shift, to within the margin.
  std::vector<Eigen::Vector3d> points;
  for (double phi = 0; phi < 40; phi += 4)
    points.push_back(OnCylinder(0.01, phi * kDeg, 0.003));
  points.push_back(OnCylinder(0.01, 10 * kDeg, 0.007));
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(0, 0, -0.02);
  const MeridianBox box = MeridianMap(t)(BoundSector(points));
  EXPECT_NEAR(box.r_min, 0.01, 1e-8);
  EXPECT_NEAR(box.r_max, 0.01, 1e-8);
  EXPECT_NEAR(box.z_min, -0.017, 1e-8);
  EXPECT_NEAR(box.z_max, -0.013, 1e-8);
  // A lateral shift of 30 um towards the middle of the arc moves r by at
  // most 30 um outwards, and towards the arc's far side by less.
  t.translation() += Eigen::AngleAxisd(1.0 + 20 * kDeg, Eigen::Vector3d::UnitZ()) *
                     Eigen::Vector3d(30e-6, 0, 0);
  const MeridianBox shifted = MeridianMap(t)(BoundSector(points));
  EXPECT_NEAR(shifted.r_max, 0.01 + 30e-6, 1e-7);
  EXPECT_GT(shifted.r_min, 0.01 + 30e-6 * std::cos(20 * kDeg) - 1e-7);
}

TEST(MeridianBoxClear, AgreesWithPointQueriesOnAGrid) {
  // A box the test calls clear holds no grid point inside the solid; a box
  // holding one is never called clear. The chamfered bore and peg profiles.
  rng::Stream s({20261123, 2}, 0, rng::Purpose::kTest);
  int clear = 0, blocked = 0;
  for (const geometry::Shape& shape :
       {testing::ChamferedBore(), testing::ChamferedPeg()}) {
    const SignedDistance field(shape);
    for (int trial = 0; trial < 2000; ++trial) {
      const double r0 = 0.035 * s.Uniform(), z0 = 0.11 * s.Uniform() - 0.06;
      const double size = trial % 2 == 0 ? 2e-3 * s.Uniform() : 40e-6 * s.Uniform();
      const MeridianBox box{r0, r0 + size, z0, z0 + size * 2 * s.Uniform()};
      bool inside = false;
      for (int i = 0; i <= 20 && !inside; ++i)
        for (int j = 0; j <= 20 && !inside; ++j) {
          const double r = box.r_min + (box.r_max - box.r_min) * i / 20.0;
          const double z = box.z_min + (box.z_max - box.z_min) * j / 20.0;
          const std::optional<Distance> d = field.Penetration({r, 0, z});
          inside = d && d->distance < 0;
        }
      const bool called_clear = field.MeridianBoxClear(box);
      if (inside) {
        EXPECT_FALSE(called_clear) << trial;
      }
      (called_clear ? clear : blocked)++;
    }
  }
  EXPECT_GT(clear, 500);
  EXPECT_GT(blocked, 500);
}

TEST(MeridianBoxClear, ABoxInTheBoreBesideItsWall) {
  const SignedDistance bore(testing::ChamferedBore());
  const double wall = testing::kBoreRadius;
  EXPECT_TRUE(
      bore.MeridianBoxClear({0.0099, wall - 1e-6, -0.03, -0.002}));  // in the hole
  EXPECT_FALSE(
      bore.MeridianBoxClear({0.0099, wall + 1e-6, -0.03, -0.002}));   // reaches the wall
  EXPECT_FALSE(bore.MeridianBoxClear({0.012, 0.013, -0.03, -0.02}));  // inside the block
  EXPECT_TRUE(bore.MeridianBoxClear({0.0, 0.005, 0.001, 0.01}));      // above it
  EXPECT_FALSE(SignedDistance(geometry::Box{Eigen::Vector3d(1, 1, 1)})
                   .MeridianBoxClear({5, 6, 5, 6}));  // a box field cannot tell
}

}  // namespace
}  // namespace vahf::contact
