// Tests of BoundPoints (geometry/bounding_sphere.h): the sphere is centred on
// the bounding box, holds every point, and touches the farthest one.
#include "vahf/geometry/bounding_sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace vahf::geometry {
namespace {

Eigen::Vector3d Same(const Eigen::Vector3d& p) { return p; }

TEST(BoundPoints, OnePointIsASphereOfRadiusZero) {
  const std::vector<Eigen::Vector3d> points = {{1, -2, 3}};
  const BoundingSphere s = BoundPoints(points.begin(), points.end(), Same);
  EXPECT_EQ(s.centre, Eigen::Vector3d(1, -2, 3));
  EXPECT_EQ(s.radius, 0.0);
}

TEST(BoundPoints, CentredOnTheBoxAndReachingTheFarthestPoint) {
  // A box's corners 0..2 x 0..4 x 0..6 plus an inner point: the box centre is
  // (1, 2, 3) and every corner lies sqrt(1 + 4 + 9) from it.
  std::vector<Eigen::Vector3d> points = {{0.5, 0.5, 0.5}};
  for (double x : {0.0, 2.0})
    for (double y : {0.0, 4.0})
      for (double z : {0.0, 6.0}) points.emplace_back(x, y, z);
  const BoundingSphere s = BoundPoints(points.begin(), points.end(), Same);
  EXPECT_EQ(s.lo, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(s.hi, Eigen::Vector3d(2, 4, 6));
  EXPECT_EQ(s.centre, Eigen::Vector3d(1, 2, 3));
  EXPECT_DOUBLE_EQ(s.radius, std::sqrt(14.0));
  for (const Eigen::Vector3d& p : points) EXPECT_LE((p - s.centre).norm(), s.radius);
}

TEST(BoundPoints, ReadsThePositionThroughTheProjectionOverASubrange) {
  struct Item {
    int id;
    Eigen::Vector3d at;
  };
  const std::vector<Item> items = {{0, {100, 100, 100}}, {1, {0, 0, 0}}, {2, {0, 0, 2}}};
  const BoundingSphere s =
      BoundPoints(items.begin() + 1, items.end(), [](const Item& i) { return i.at; });
  EXPECT_EQ(s.centre, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(s.radius, 1.0);
}

}  // namespace
}  // namespace vahf::geometry
