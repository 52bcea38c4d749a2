// Eqs. 1-3 and the angles and distance behind f, g and r, on geometry whose
// answers follow by hand.
#include "vahf/human/factors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "vahf/human/factor_curves.h"

namespace vahf::human {
namespace {

Posture Upright() {
  Operator op;
  op.height = 1.75;
  op.arm_length = 0.74;
  op.position = {0.0, -0.45};
  op.facing_deg = 90.0;
  return StandingPosture(op);
}

TEST(Visibility, Eq1) {
  EXPECT_DOUBLE_EQ(Visibility(100, 100), 1.0);  // nothing hides the part
  EXPECT_DOUBLE_EQ(Visibility(0, 100), 0.0);    // wholly hidden
  EXPECT_DOUBLE_EQ(Visibility(25, 100), 0.25);
  EXPECT_DOUBLE_EQ(Visibility(0, 0), 0.0);  // V_b = 0: out of view, nothing seen
}

TEST(Coefficients, Eqs2And3) {
  EXPECT_DOUBLE_EQ(VisionCoefficient(1.0, 0.95), 1.0 - 0.95);
  EXPECT_DOUBLE_EQ(VisionCoefficient(0.4, 0.88), 1.0 - 0.4 * 0.88);
  EXPECT_DOUBLE_EQ(VisionCoefficient(0.0, 0.7), 1.0);  // invisible: f no longer matters
  EXPECT_DOUBLE_EQ(ComfortCoefficient(0.9, 1.0, 1.0), 1.0 - 0.95);
  EXPECT_DOUBLE_EQ(ComfortCoefficient(0.8, 0.85, 0.08), 1.0 - 0.825 * 0.08);
  EXPECT_DOUBLE_EQ(ComfortCoefficient(1.0, 1.0, 0.0), 1.0);
}

TEST(Angles, SightAndGlance) {
  const Posture p = Upright();
  // A part straight below the eye.
  const Eigen::Vector3d below = p.eye - Eigen::Vector3d(0, 0, 0.6);
  EXPECT_NEAR(GlanceAngleDeg(p, below), 0.0, 1e-9);  // looking straight down
  EXPECT_NEAR(SightAngleDeg(p, below, Eigen::Vector3d(0, 0, -1)), 0.0, 1e-9);
  EXPECT_NEAR(SightAngleDeg(p, below, Eigen::Vector3d(1, 0, 0)), 90.0, 1e-9);
  // Level gaze straight ahead, and up.
  EXPECT_NEAR(GlanceAngleDeg(p, p.eye + Eigen::Vector3d(0, 0.5, 0)), 90.0, 1e-9);
  EXPECT_NEAR(GlanceAngleDeg(p, p.eye + Eigen::Vector3d(0, 0, 0.5)), 180.0, 1e-9);
  // 45 degrees below level, ahead.
  EXPECT_NEAR(GlanceAngleDeg(p, p.eye + Eigen::Vector3d(0, 0.5, -0.5)), 45.0, 1e-9);
  // A part centred on the eye has no sight line: both angles are 0 (this
  // once aborted a trial, "angle of a zero vector").
  EXPECT_EQ(GlanceAngleDeg(p, p.eye), 0.0);
  EXPECT_EQ(SightAngleDeg(p, p.eye, Eigen::Vector3d(1, 0, 0)), 0.0);
}

TEST(ShoulderDistance, TheFartherShoulder) {
  const Posture p = Upright();
  const Eigen::Vector3d part = p.right_shoulder + Eigen::Vector3d(0.1, 0.3, 0.0);
  EXPECT_DOUBLE_EQ(ShoulderDistance(p, part), (p.left_shoulder - part).norm());
}

TEST(EvaluateFactors, ByHand) {
  const Posture p = Upright();
  const FactorCurves curves{DefaultSightCurve().Build(), ReachCurve{}.Build(0.74, 1.75),
                            DefaultGlanceCurve().Build()};
  // Part 0.45 m ahead of and 0.45 m below the eye, moving straight down.
  const Eigen::Vector3d part = p.eye + Eigen::Vector3d(0, 0.45, -0.45);
  const FactorValues v = EvaluateFactors(curves, p, part, Eigen::Vector3d(0, 0, -1), 0.5);
  EXPECT_NEAR(v.sight_angle_deg, 45.0, 1e-9);
  EXPECT_DOUBLE_EQ(v.f, 1.0);
  EXPECT_DOUBLE_EQ(v.eta, 0.5);
  EXPECT_NEAR(v.glance_angle_deg, 45.0, 1e-9);
  EXPECT_DOUBLE_EQ(v.g, 1.0);
  // Shoulders: 0.118 * 1.75 m below the eye, 0.259 * 1.75 / 2 m to each side.
  const double dz = 0.45 - (0.936 - 0.818) * 1.75;
  const double dx = 0.259 * 1.75 / 2;
  const double d = std::sqrt(dx * dx + 0.45 * 0.45 + dz * dz);
  EXPECT_NEAR(v.shoulder_distance, d, 1e-12);
  const double d1 = 0.85 * 0.74;
  EXPECT_LT(d, d1);
  EXPECT_DOUBLE_EQ(v.r, 1.0);
  EXPECT_DOUBLE_EQ(v.lambda_c, 1.0 - 0.5 * (1.0 + 1.0) * 0.5);
}

}  // namespace
}  // namespace vahf::human
