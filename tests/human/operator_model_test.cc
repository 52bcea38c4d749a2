// The standing operator: landmarks at Winter's fractions of stature, a body
// plane whose normal is the facing direction and whose down axis is -z, and a
// posture that turns with the operator.
#include "vahf/human/operator_model.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace vahf::human {
namespace {

Operator Standing(double facing_deg) {
  Operator op;
  op.height = 1.70;
  op.arm_length = 0.72;
  op.position = {0.3, -0.4};
  op.facing_deg = facing_deg;
  return op;
}

TEST(StandingPosture, LandmarksAtWintersFractions) {
  const Posture p = StandingPosture(Standing(90.0));
  EXPECT_NEAR(p.eye.z(), 0.936 * 1.70, 1e-12);
  EXPECT_NEAR(p.left_shoulder.z(), 0.818 * 1.70, 1e-12);
  EXPECT_NEAR(p.right_shoulder.z(), 0.818 * 1.70, 1e-12);
  EXPECT_NEAR((p.left_shoulder - p.right_shoulder).norm(), 0.259 * 1.70, 1e-12);
  EXPECT_NEAR(p.body_centre.z(), 0.5 * (0.818 + 0.530) * 1.70, 1e-12);
  EXPECT_NEAR(p.eye.x(), 0.3, 1e-12);
  EXPECT_NEAR(p.eye.y(), -0.4, 1e-12);
  // Facing +y: the left shoulder is towards -x.
  EXPECT_LT(p.left_shoulder.x(), p.right_shoulder.x());
}

TEST(StandingPosture, BodyPlaneAxes) {
  const Posture p = StandingPosture(Standing(90.0));
  EXPECT_NEAR((p.forward - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((p.down + Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  // The shoulders and the body centre lie in the plane.
  EXPECT_NEAR(p.forward.dot(p.left_shoulder - p.body_centre), 0.0, 1e-12);
  EXPECT_NEAR(p.forward.dot(p.right_shoulder - p.body_centre), 0.0, 1e-12);
}

TEST(StandingPosture, TurnsWithTheOperator) {
  const Posture a = StandingPosture(Standing(0.0));
  const Posture b = StandingPosture(Standing(120.0));
  const Eigen::Vector3d pivot(0.3, -0.4, 0.0);
  const Eigen::AngleAxisd turn(120.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR((turn * (a.left_shoulder - pivot) + pivot - b.left_shoulder).norm(), 0,
              1e-12);
  EXPECT_NEAR((turn * a.forward - b.forward).norm(), 0, 1e-12);
}

TEST(BodyPlaneFrom, LeaningBody) {
  // A trunk bent 30 degrees forward about the shoulder line (x axis), facing +y.
  const double bend = 30.0 * M_PI / 180.0;
  const Eigen::Vector3d ls(-0.2, 0, 1.4), rs(0.2, 0, 1.4);
  const Eigen::Vector3d centre(0, -0.3 * std::sin(bend), 1.4 - 0.3 * std::cos(bend));
  Eigen::Vector3d forward, down;
  BodyPlaneFrom(ls, rs, centre, Eigen::Vector3d::UnitY(), &forward, &down);
  EXPECT_NEAR(forward.dot(down), 0.0, 1e-12);
  EXPECT_NEAR(down.z(), -std::cos(bend), 1e-12);
  EXPECT_GT(forward.y(), 0.0);
}

}  // namespace
}  // namespace vahf::human
