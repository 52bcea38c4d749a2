// Human factors from a sensor track (Sec. 5.1) on a track whose every factor
// follows by hand from right angles and the default curves (docs/parameters.md):
//   f: 0.5 at 0 deg, 1 on [30, 45] deg, 0 at 180 deg   (Fig. 3)
//   g: 0.5 at 0 deg, 1 on [30, 90] deg, 0 at 180 deg   (Fig. 5)
//   r: 1 to D1 = 0.85 l, 0.5 at D2 = 0.39 h, 0 at D3 = 0.68 h (Fig. 4); for the
//      operator here, l = 0.74 m and h = 1.75 m: D1 = 0.629, D2 = 0.6825,
//      D3 = 1.19 m.
#include "vahf/data/track_factors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "support/standing_operator.h"
#include "vahf/core/error.h"
#include "vahf/human/factor_curves.h"
#include "vahf/human/operator_model.h"

namespace vahf::data {
namespace {

using Eigen::Vector3d;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kArm = 0.74, kHeight = 1.75;
constexpr double kD1 = 0.85 * kArm, kD2 = 0.39 * kHeight;

human::FactorCurves Curves() {
  return {human::DefaultSightCurve().Build(), human::ReachCurve{}.Build(kArm, kHeight),
          human::DefaultGlanceCurve().Build()};
}

// The operator stands still, facing +x, the head leaning over the left
// shoulder towards the part (y = 0): support/standing_operator.h, whose
// geometry the factors below are worked out from.
TrackSample Sample(int line, double time, const Vector3d& part, double V) {
  return testing::StandingSample(line, time, part, V);
}

// The part is lowered 0.4 m, pauses, then drawn 0.4 m towards the operator.
SensorTrack HandTrack() {
  SensorTrack t;
  t.file = "tracks/hand.csv";
  t.operator_id = "op1";
  t.condition = "good";
  t.repetition = 1;
  t.samples = {Sample(2, 0.0, {0, 0, 0.4}, 1.0),    // level with the brow, 0.4 m ahead
               Sample(3, 0.5, {0, 0, 0}, 0.5),      // lowered
               Sample(4, 1.0, {0, 0, 0}, kNaN),     // still; the camera took no picture
               Sample(5, 1.5, {-0.4, 0, 0}, 0.8)};  // drawn in, under the brow
  return t;
}

// r on the falling segment between D1 and D2.
double ReachBetweenD1AndD2(double d) { return 1.0 - 0.5 * (d - kD1) / (kD2 - kD1); }

TEST(FactorsFromTrack, ByHand) {
  const std::vector<TrackFactors> out = FactorsFromTrack(HandTrack(), Curves());
  ASSERT_EQ(out.size(), 3u);  // samples 1-3: sample 0 has no P_{i-1}

  // Sample 1, P = (0, 0, 0). Motion P_1 - P_0 = (0, 0, -0.4): straight down.
  // Sight line P - E = (0.4, 0, -0.4): Ang = 45 deg, the plateau's end, f = 1.
  // Anp, the sight line against down (-z): 45 deg, on g's plateau, g = 1.
  // Shoulders: |L - P| = |(-0.5, 0, 0.2)| = sqrt(0.29) = 0.539 m (under D1),
  // |R - P| = |(-0.5, -0.4, 0.2)| = sqrt(0.45) = 0.6708 m, the farther: between
  // D1 and D2, r = 1 - 0.5 (0.6708 - 0.629) / 0.0535 = 0.6092.
  // V = 0.5: eta = 1 - 0.5 * 1 = 0.5; lambda_c = 1 - (0.6092 + 1) / 2 * 0.5
  // = 0.5977.
  const double r1 = ReachBetweenD1AndD2(std::sqrt(0.45));
  EXPECT_NEAR(r1, 0.60916, 1e-5);
  const TrackFactors& a = out[0];
  EXPECT_EQ(a.line, 3);
  EXPECT_DOUBLE_EQ(a.time, 0.5);
  EXPECT_EQ(a.motion, MotionSource::kMeasured);
  EXPECT_NEAR((a.motion_direction - Vector3d(0, 0, -1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(a.values.sight_angle_deg, 45.0, 1e-12);
  EXPECT_NEAR(a.values.f, 1.0, 1e-12);
  EXPECT_NEAR(a.values.glance_angle_deg, 45.0, 1e-12);
  EXPECT_NEAR(a.values.g, 1.0, 1e-12);
  EXPECT_NEAR(a.values.shoulder_distance, std::sqrt(0.45), 1e-12);
  EXPECT_NEAR(a.values.r, r1, 1e-12);
  EXPECT_NEAR(a.values.V, 0.5, 1e-12);
  EXPECT_NEAR(a.values.eta, 0.5, 1e-12);
  EXPECT_NEAR(a.values.lambda_c, 1.0 - 0.5 * (r1 + 1.0) * 0.5, 1e-12);
  EXPECT_NEAR(a.values.lambda_c, 0.59771, 1e-5);

  // Sample 2: the part has not moved, so the direction of sample 1 is carried
  // on; the posture and P are those of sample 1, so are Ang, f, r and g. No V
  // in the track and none given: eta and lambda_c are NaN.
  const TrackFactors& b = out[1];
  EXPECT_EQ(b.line, 4);
  EXPECT_EQ(b.motion, MotionSource::kCarried);
  EXPECT_NEAR((b.motion_direction - Vector3d(0, 0, -1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(b.values.sight_angle_deg, 45.0, 1e-12);
  EXPECT_NEAR(b.values.f, 1.0, 1e-12);
  EXPECT_NEAR(b.values.r, r1, 1e-12);
  EXPECT_NEAR(b.values.g, 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(b.values.V));
  EXPECT_TRUE(std::isnan(b.values.eta));
  EXPECT_TRUE(std::isnan(b.values.lambda_c));

  // Sample 3, P = (-0.4, 0, 0). Motion (-0.4, 0, 0): towards the operator.
  // Sight line (0, 0, -0.4), straight down: Ang = 90 deg, f = 1 - (90 - 45) /
  // (180 - 45) = 2/3; Anp = 0 deg, g = 0.5. Shoulders: |L - P| = sqrt(0.05),
  // |R - P| = |(-0.1, -0.4, 0.2)| = sqrt(0.21) = 0.458 m, under D1: r = 1.
  // V = 0.8: eta = 1 - 0.8 * 2/3 = 7/15; lambda_c = 1 - (1 + 0.5) / 2 * 0.8 = 0.4.
  const TrackFactors& c = out[2];
  EXPECT_EQ(c.motion, MotionSource::kMeasured);
  EXPECT_NEAR((c.motion_direction - Vector3d(-1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(c.values.sight_angle_deg, 90.0, 1e-12);
  EXPECT_NEAR(c.values.f, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(c.values.glance_angle_deg, 0.0, 1e-12);
  EXPECT_NEAR(c.values.g, 0.5, 1e-12);
  EXPECT_NEAR(c.values.shoulder_distance, std::sqrt(0.21), 1e-12);
  EXPECT_NEAR(c.values.r, 1.0, 1e-12);
  EXPECT_NEAR(c.values.eta, 7.0 / 15.0, 1e-12);
  EXPECT_NEAR(c.values.lambda_c, 0.4, 1e-12);
}

// r takes the farther shoulder (Sec. 5.1: max(|P_irs - P_i|, |P_ils - P_i|)),
// whichever side it is on. In front of the left shoulder (the hand track) the
// nearer one, sqrt(0.29) m, is under D1 and would give r = 1; mirrored to the
// right shoulder (part and brow at y = -0.4), the left is the farther, again
// at sqrt(0.45) m.
TEST(FactorsFromTrack, ReachIsFromTheFartherShoulder) {
  const double r_far = ReachBetweenD1AndD2(std::sqrt(0.45));
  ASSERT_LT(std::sqrt(0.29), kD1);  // the nearer shoulder would give r = 1
  ASSERT_LT(r_far, 0.7);

  const std::vector<TrackFactors> left = FactorsFromTrack(HandTrack(), Curves());
  EXPECT_NEAR(left[0].values.shoulder_distance, std::sqrt(0.45), 1e-12);
  EXPECT_NEAR(left[0].values.r, r_far, 1e-12);

  SensorTrack mirrored = HandTrack();
  for (TrackSample& s : mirrored.samples) {
    s.part.y() -= 0.4;
    s.brow.y() -= 0.4;
  }
  const std::vector<TrackFactors> right = FactorsFromTrack(mirrored, Curves());
  // |L - P| = |(-0.5, 0.4, 0.2)| = sqrt(0.45); |R - P| = sqrt(0.29).
  EXPECT_NEAR(right[0].values.shoulder_distance, std::sqrt(0.45), 1e-12);
  EXPECT_NEAR(right[0].values.r, r_far, 1e-12);
}

// The motion runs from P_{i-1} to P_i. The hand track's sample 1 is lowered:
// against the sight line (0.4, 0, -0.4) that is Ang = 45 deg and f = 1; the
// wrong way round, P_{i-1} - P_i = +z, would be Ang = 135 deg and f = 1 -
// 90 / 135 = 1/3, eta = 1 - 0.5 / 3 = 5/6.
TEST(FactorsFromTrack, MotionRunsFromThePreviousSample) {
  const std::vector<TrackFactors> out = FactorsFromTrack(HandTrack(), Curves());
  EXPECT_NEAR(out[0].motion_direction.z(), -1.0, 1e-12);
  EXPECT_NEAR(out[0].values.sight_angle_deg, 45.0, 1e-12);
  EXPECT_NEAR(out[0].values.f, 1.0, 1e-12);
  EXPECT_NEAR(out[0].values.eta, 0.5, 1e-12);

  // Raised instead, from (0, 0, -0.4) to (0, 0, 0): Ang = 135 deg, f = 1/3.
  SensorTrack raised = HandTrack();
  raised.samples[0].part = Vector3d(0, 0, -0.4);
  const std::vector<TrackFactors> up = FactorsFromTrack(raised, Curves());
  EXPECT_NEAR(up[0].values.sight_angle_deg, 135.0, 1e-12);
  EXPECT_NEAR(up[0].values.f, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(up[0].values.eta, 1.0 - 0.5 / 3.0, 1e-12);
}

// A part still since the track began has no direction: Ang, f and eta are
// NaN, while r, g and lambda_c, which need none, are given. At P = (0, 0, 0.4)
// the sight line (0.4, 0, 0) is level, Anp = 90 deg, g = 1; the shoulders are
// sqrt(0.29) and sqrt(0.45) m away as in sample 1, so r is too.
TEST(FactorsFromTrack, StillFromTheStartHasNoDirection) {
  SensorTrack t = HandTrack();
  t.samples[1].part = t.samples[0].part;
  const std::vector<TrackFactors> out = FactorsFromTrack(t, Curves());
  const TrackFactors& a = out[0];
  EXPECT_EQ(a.motion, MotionSource::kNone);
  EXPECT_TRUE(std::isnan(a.motion_direction.x()));
  EXPECT_TRUE(std::isnan(a.values.sight_angle_deg));
  EXPECT_TRUE(std::isnan(a.values.f));
  EXPECT_TRUE(std::isnan(a.values.eta));
  const double r = ReachBetweenD1AndD2(std::sqrt(0.45));
  EXPECT_NEAR(a.values.glance_angle_deg, 90.0, 1e-12);
  EXPECT_NEAR(a.values.g, 1.0, 1e-12);
  EXPECT_NEAR(a.values.r, r, 1e-12);
  EXPECT_NEAR(a.values.lambda_c, 1.0 - 0.5 * (r + 1.0) * 0.5, 1e-12);  // V = 0.5
  // Sample 2 moves, from (0, 0, 0.4) to (0, 0, 0): measured again.
  EXPECT_EQ(out[1].motion, MotionSource::kMeasured);
  EXPECT_NEAR(out[1].values.f, 1.0, 1e-12);
}

// A step no larger than still_distance counts as still: sensor jitter does
// not turn into a direction.
TEST(FactorsFromTrack, StillDistance) {
  SensorTrack t = HandTrack();
  t.samples[1].part = t.samples[0].part + Vector3d(0, 0, 1e-4);
  EXPECT_EQ(FactorsFromTrack(t, Curves())[0].motion, MotionSource::kMeasured);
  TrackFactorOptions options;
  options.still_distance = 1e-3;
  const std::vector<TrackFactors> out = FactorsFromTrack(t, Curves(), options);
  EXPECT_EQ(out[0].motion, MotionSource::kNone);
  EXPECT_EQ(out[1].motion, MotionSource::kMeasured);  // then 0.4 m down
}

// Without a camera value, a V the caller gives is used: sample 2 with V = 1
// has eta = 1 - f = 0 and lambda_c = 1 - (r + 1) / 2 = 0.1954.
TEST(FactorsFromTrack, GivenVisibility) {
  TrackFactorOptions options;
  options.visibility = 1.0;
  const std::vector<TrackFactors> out = FactorsFromTrack(HandTrack(), Curves(), options);
  const double r = ReachBetweenD1AndD2(std::sqrt(0.45));
  EXPECT_NEAR(out[1].values.V, 1.0, 1e-12);
  EXPECT_NEAR(out[1].values.eta, 0.0, 1e-12);
  EXPECT_NEAR(out[1].values.lambda_c, 1.0 - 0.5 * (r + 1.0), 1e-12);
  EXPECT_NEAR(out[1].values.lambda_c, 0.19542, 1e-5);
  EXPECT_NEAR(out[0].values.V, 0.5, 1e-12);  // the track's own V wins
}

// A track made from the simulation's standing operator gives exactly the
// factors the simulation computes for that posture.
TEST(FactorsFromTrack, AgreesWithTheSimulation) {
  human::Operator op;
  op.height = kHeight;
  op.arm_length = kArm;
  op.position = {0.0, -0.45};
  op.facing_deg = 90.0;
  const human::Posture p = human::StandingPosture(op);
  SensorTrack t;
  t.file = "tracks/standing.csv";
  for (int i = 0; i < 2; ++i) {
    TrackSample s;
    s.time = i;
    s.part = p.eye + Vector3d(0.05, 0.45, i == 0 ? -0.3 : -0.45);
    s.brow = p.eye;
    s.left_shoulder = p.left_shoulder;
    s.right_shoulder = p.right_shoulder;
    s.body = p.body_centre;
    s.visibility = 0.7;
    t.samples.push_back(s);
  }
  const human::FactorCurves curves = Curves();
  const human::FactorValues want = human::EvaluateFactors(
      curves, p, t.samples[1].part, t.samples[1].part - t.samples[0].part, 0.7);
  const human::FactorValues got = FactorsFromTrack(t, curves)[0].values;
  EXPECT_NEAR(got.sight_angle_deg, want.sight_angle_deg, 1e-12);
  EXPECT_NEAR(got.f, want.f, 1e-12);
  EXPECT_NEAR(got.shoulder_distance, want.shoulder_distance, 1e-12);
  EXPECT_NEAR(got.r, want.r, 1e-12);
  EXPECT_NEAR(got.glance_angle_deg, want.glance_angle_deg, 1e-12);
  EXPECT_NEAR(got.g, want.g, 1e-12);
  EXPECT_NEAR(got.eta, want.eta, 1e-12);
  EXPECT_NEAR(got.lambda_c, want.lambda_c, 1e-12);
}

void ExpectInputError(const SensorTrack& t, const std::string& where,
                      const std::string& rule) {
  try {
    FactorsFromTrack(t, Curves());
    ADD_FAILURE() << "no InputError; expected one at " << where;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), t.file);
    EXPECT_EQ(e.where(), where);
    EXPECT_NE(e.rule().find(rule), std::string::npos) << e.rule();
  }
}

TEST(FactorsFromTrack, BadSamplesAreInputErrors) {
  SensorTrack t = HandTrack();
  t.samples[2].brow = t.samples[2].part;
  ExpectInputError(t, "line 4", "no sight line");

  t = HandTrack();
  t.samples[3].body = 0.5 * (t.samples[3].left_shoulder + t.samples[3].right_shoulder);
  ExpectInputError(t, "line 5", "collinear");

  t = HandTrack();
  t.samples[1].right_shoulder = t.samples[1].left_shoulder;
  ExpectInputError(t, "line 3", "collinear");
}

}  // namespace
}  // namespace vahf::data
