// Shapes and a pose shared by the rim tests: the peg_in_hole scene's chamfered
// bore block and chamfered peg (experiments/scenes/peg_in_hole.json), and the
// peg tilted into the bore's mouth with the bore's chamfer-to-wall edge a
// given depth inside its side wall.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "vahf/geometry/shape.h"

namespace vahf::contact::testing {

// A profile from its vertices, the closing repeat added.
inline geometry::Shape Revolved(std::vector<geometry::ProfilePoint> p) {
  p.push_back(p.front());
  return geometry::MakeRevolvedProfile(p);
}

// Bore radius 10.05 mm, 40 mm deep, a 1 mm x 45 deg chamfer at its mouth
// (z = 0), in a block 30 mm in radius and 50 mm high.
constexpr double kBoreRadius = 0.01005;
inline geometry::Shape ChamferedBore() {
  return Revolved({{0.0, -0.05},
                   {0.03, -0.05},
                   {0.03, 0.0},
                   {0.01105, 0.0},
                   {kBoreRadius, -0.001},
                   {kBoreRadius, -0.04},
                   {0.0, -0.04}});
}

// Radius 10 mm, 50 mm long, a 0.5 mm x 45 deg chamfer at its bottom (z = 0).
constexpr double kPegRadius = 0.01;
inline geometry::Shape ChamferedPeg() {
  return Revolved(
      {{0, 0}, {0.0095, 0}, {kPegRadius, 0.0005}, {kPegRadius, 0.05}, {0, 0.05}});
}

// The peg tilted by 2 deg about x, top towards +y, with the point of the
// bore's chamfer-to-wall circle at azimuth 90 deg, (0, 10.05 mm, -1 mm) in the
// bore frame (placed at bore_at), `depth` inside the peg's side wall at
// 1.49 mm up the peg's axis: midway between two bands of its 1 mm shell,
// whose centres are 0.99 mm apart. Below that point the bore wall is inside
// the peg over depth / tan(2 deg) (0.29 mm at 10 um), above it the chamfer
// over depth / (1 - tan(2 deg)): no shell point is in either.
constexpr double kTiltRad = 2.0 * M_PI / 180;
inline Eigen::Isometry3d TiltedPegPose(const Eigen::Vector3d& bore_at, double depth) {
  const double up_axis = 1.49e-3;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::AngleAxisd(-kTiltRad, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d rim_point(0, kBoreRadius, -0.001);
  pose.translation() = bore_at + rim_point -
                       pose.linear() * Eigen::Vector3d(0, kPegRadius - depth, up_axis);
  return pose;
}

}  // namespace vahf::contact::testing
