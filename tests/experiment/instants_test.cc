// Tests of FindInstants on hand-built trials (no simulation): a is the first
// trace row with a contact force, b the largest tilt among contact rows at or
// after a, c the first row after b whose tilt is below the completion angle, d
// the final row of a completed trial; an instant the trial never reached is
// absent (no contact: no a, b or c; never realigned: no c; not completed: no d).
#include "vahf/experiment/instants.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "vahf/sim/trial_result.h"

namespace vahf::experiment {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCompletionDeg = 1.0;

double Rad(double deg) { return deg * kPi / 180.0; }

// One trace row at `time`: the part tilted by `tilt_deg` about the world x
// axis (so its z axis makes that angle with an identity target's), with a
// normal contact force of `contact_n` newtons (0: not in contact).
sim::TraceRow Row(double time, double tilt_deg, double contact_n) {
  sim::TraceRow row;
  row.time = time;
  row.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(Rad(tilt_deg), Eigen::Vector3d::UnitX()));
  row.contact_force = Eigen::Vector3d(0.0, contact_n, 0.0);
  return row;
}

// A trial with these trace rows; completed, its final row at `end_time`.
sim::TrialResult Trial(std::vector<sim::TraceRow> rows,
                       sim::Status status = sim::Status::kCompleted,
                       double end_time = 100.0) {
  sim::TrialResult t;
  t.status = status;
  t.end_time = end_time;
  if (status == sim::Status::kCompleted) t.completion_time = end_time;
  t.trace = std::move(rows);
  t.final_row = Row(end_time, 0.1, 3.0);
  t.final_row.work = 42.0;  // tells it apart from any trace row
  return t;
}

Instants Find(const sim::TrialResult& trial) {
  return FindInstants(trial, Eigen::Matrix3d::Identity(), kCompletionDeg);
}

// The time of an instant, or -1 when it is absent.
double TimeOf(const std::optional<sim::TraceRow>& row) { return row ? row->time : -1.0; }

TEST(TiltDeg, AngleBetweenThePartAndTargetAxes) {
  EXPECT_NEAR(TiltDeg(Row(0, 7.5, 0), Eigen::Matrix3d::Identity()), 7.5, 1e-12);
  EXPECT_NEAR(TiltDeg(Row(0, 0, 0), Eigen::Matrix3d::Identity()), 0.0, 1e-12);
  // A turn about the part's own axis is no tilt.
  sim::TraceRow spun;
  spun.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(Rad(70), Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(TiltDeg(spun, Eigen::Matrix3d::Identity()), 0.0, 1e-12);
  // Measured from the target's axis, not the world's: a target turned 90 deg
  // about y, and a part turned 90 deg about y (aligned) or not turned (90 deg).
  const Eigen::Matrix3d target =
      Eigen::AngleAxisd(Rad(90), Eigen::Vector3d::UnitY()).toRotationMatrix();
  sim::TraceRow aligned;
  aligned.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(Rad(90), Eigen::Vector3d::UnitY()));
  EXPECT_NEAR(TiltDeg(aligned, target), 0.0, 1e-12);
  EXPECT_NEAR(TiltDeg(Row(0, 0, 0), target), 90.0, 1e-12);
}

TEST(FindInstants, TypicalTrialHasAllFour) {
  const sim::TrialResult trial = Trial({
      Row(0.0, 3.0, 0.0),  // approaching, no contact
      Row(0.1, 2.0, 5.0),  // a: first contact
      Row(0.2, 6.0, 5.0),
      Row(0.3, 9.0, 8.0),  // b: largest tilt in contact
      Row(0.4, 4.0, 8.0),
      Row(0.5, 0.5, 8.0),  // c: first below 1 deg after b
      Row(0.6, 0.2, 8.0),
  });
  const Instants in = Find(trial);
  EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.1);
  EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.3);
  EXPECT_DOUBLE_EQ(TimeOf(in.c), 0.5);
  ASSERT_TRUE(in.d);
  EXPECT_DOUBLE_EQ(in.d->time, 100.0);
  EXPECT_DOUBLE_EQ(in.d->work, 42.0);  // the final row, not the last trace row
  // The rows are returned whole.
  EXPECT_NEAR(TiltDeg(*in.b, Eigen::Matrix3d::Identity()), 9.0, 1e-12);
  EXPECT_EQ(in.a->contact_force, Eigen::Vector3d(0.0, 5.0, 0.0));
}

TEST(FindInstants, AnyNonZeroContactForceComponentIsContact) {
  sim::TraceRow touch = Row(0.2, 2.0, 0.0);
  touch.contact_force = Eigen::Vector3d(0.0, 0.0, -1e-9);
  sim::TraceRow rubbing = Row(0.1, 2.0, 0.0);
  rubbing.friction_force =
      Eigen::Vector3d(1.0, 0.0, 0.0);  // friction alone is not contact
  const Instants in =
      Find(Trial({Row(0.0, 2.0, 0.0), rubbing, touch, Row(0.3, 0.5, 0.0)}));
  EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.2);
  EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.2);
  EXPECT_DOUBLE_EQ(TimeOf(in.c), 0.3);
}

TEST(FindInstants, NoContactMeansNoABOrC) {
  const sim::TrialResult trial = Trial({
      Row(0.0, 5.0, 0.0),
      Row(0.1, 12.0, 0.0),
      Row(0.2, 0.5, 0.0),
      Row(0.3, 0.1, 0.0),
  });
  const Instants in = Find(trial);
  EXPECT_FALSE(in.a);
  EXPECT_FALSE(in.b);
  EXPECT_FALSE(in.c);
  ASSERT_TRUE(in.d);  // it completed, without touching anything
  EXPECT_DOUBLE_EQ(in.d->time, 100.0);
}

TEST(FindInstants, EmptyTraceHasOnlyD) {
  const Instants in = Find(Trial({}));
  EXPECT_FALSE(in.a);
  EXPECT_FALSE(in.b);
  EXPECT_FALSE(in.c);
  EXPECT_TRUE(in.d);
  const Instants timed_out = Find(Trial({}, sim::Status::kTimeout));
  EXPECT_FALSE(timed_out.a || timed_out.b || timed_out.c || timed_out.d);
}

TEST(FindInstants, NeverRealignedMeansNoC) {
  const sim::TrialResult trial = Trial(
      {
          Row(0.0, 2.0, 0.0), Row(0.1, 3.0, 1.0),  // a
          Row(0.2, 8.0, 1.0),                      // b
          Row(0.3, 5.0, 1.0),
          Row(0.4, 1.5, 0.0),  // back out of contact, still above 1 deg
          Row(0.5, 1.2, 1.0),  // in contact again, just above
      },
      sim::Status::kJammed, 0.5);
  const Instants in = Find(trial);
  EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.1);
  EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.2);
  EXPECT_FALSE(in.c);
  EXPECT_FALSE(in.d);
}

TEST(FindInstants, NotCompletedMeansNoD) {
  const std::vector<sim::TraceRow> rows = {Row(0.0, 2.0, 0.0), Row(0.1, 3.0, 1.0),
                                           Row(0.2, 8.0, 1.0), Row(0.3, 0.5, 1.0)};
  for (sim::Status status :
       {sim::Status::kTimeout, sim::Status::kExhausted, sim::Status::kUnreachable,
        sim::Status::kJammed, sim::Status::kNumericalFailure}) {
    const Instants in = Find(Trial(rows, status, 0.3));
    EXPECT_FALSE(in.d) << sim::StatusName(status);
    // The instants it did reach are still there.
    EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.1) << sim::StatusName(status);
    EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.2) << sim::StatusName(status);
    EXPECT_DOUBLE_EQ(TimeOf(in.c), 0.3) << sim::StatusName(status);
  }
  EXPECT_TRUE(Find(Trial(rows, sim::Status::kCompleted, 0.3)).d);
}

TEST(FindInstants, BIsTheLargestTiltAmongContactRowsOnly) {
  const sim::TrialResult trial = Trial({
      Row(0.0, 30.0, 0.0),  // before a and not in contact: the largest tilt of all
      Row(0.1, 2.0, 4.0),   // a
      Row(0.2, 20.0, 0.0),  // bounced off: larger than any contact row
      Row(0.3, 7.0, 4.0),   // b
      Row(0.4, 25.0, 0.0),  // bounced off again
      Row(0.5, 6.0, 4.0), Row(0.6, 0.3, 4.0),  // c
  });
  const Instants in = Find(trial);
  EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.1);
  EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.3);
  EXPECT_DOUBLE_EQ(TimeOf(in.c), 0.6);
}

TEST(FindInstants, BIsAWhenTheTiltOnlyFalls) {
  const Instants in = Find(Trial({
      Row(0.0, 4.0, 0.0), Row(0.1, 5.0, 2.0),  // a and b
      Row(0.2, 3.0, 2.0), Row(0.3, 0.9, 2.0),  // c
  }));
  EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.1);
  EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.1);
  EXPECT_DOUBLE_EQ(TimeOf(in.c), 0.3);
}

TEST(FindInstants, CComesAfterBNotBefore) {
  const Instants in = Find(Trial({
      Row(0.0, 0.2, 1.0),  // a: first contact, already aligned
      Row(0.1, 0.4, 1.0),  // aligned, but before b
      Row(0.2, 4.0, 1.0),  // b
      Row(0.3, 2.0, 1.0),
      Row(0.4, 0.6, 1.0),  // c
      Row(0.5, 0.1, 1.0),
  }));
  EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.0);
  EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.2);
  EXPECT_DOUBLE_EQ(TimeOf(in.c), 0.4);
}

TEST(FindInstants, TheCompletionAngleSetsC) {
  const sim::TrialResult trial = Trial({
      Row(0.0, 1.0, 1.0),  // a
      Row(0.1, 6.0, 1.0),  // b
      Row(0.2, 2.5, 1.0),
      Row(0.3, 1.5, 1.0),
      Row(0.4, 0.5, 1.0),
  });
  EXPECT_DOUBLE_EQ(TimeOf(FindInstants(trial, Eigen::Matrix3d::Identity(), 3.0).c), 0.2);
  EXPECT_DOUBLE_EQ(TimeOf(FindInstants(trial, Eigen::Matrix3d::Identity(), 2.0).c), 0.3);
  EXPECT_DOUBLE_EQ(TimeOf(FindInstants(trial, Eigen::Matrix3d::Identity(), 1.0).c), 0.4);
  EXPECT_FALSE(FindInstants(trial, Eigen::Matrix3d::Identity(), 0.25).c);
}

TEST(FindInstants, TiltIsMeasuredFromTheTargetAxis) {
  // The target is turned 10 deg about x: a part turned 10 deg is aligned.
  const Eigen::Matrix3d target =
      Eigen::AngleAxisd(Rad(10), Eigen::Vector3d::UnitX()).toRotationMatrix();
  const sim::TrialResult trial = Trial({
      Row(0.0, 10.0, 1.0),  // a: aligned with the target
      Row(0.1, 0.0, 1.0),   // b: 10 deg from the target (0 deg from the world's z)
      Row(0.2, 4.0, 1.0), Row(0.3, 9.5, 1.0),  // c
  });
  const Instants in = FindInstants(trial, target, kCompletionDeg);
  EXPECT_DOUBLE_EQ(TimeOf(in.a), 0.0);
  EXPECT_DOUBLE_EQ(TimeOf(in.b), 0.1);
  EXPECT_DOUBLE_EQ(TimeOf(in.c), 0.3);
}

}  // namespace
}  // namespace vahf::experiment
