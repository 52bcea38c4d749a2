// The contact's analytic derivative (contact_jacobian.h, PenaltyContact with a
// ContactJacobian) against central differences of the contact forces, in
// geometries where it is exact: a box tilted into a flat floor (face contact,
// friction above and below the transition speed, with and without the
// hardening barrier and its tangent), the box's own edges (moving rims) in the
// floor, and a pedestal's edges (fixed rims) in the box's flat bottom face,
// where the box's normal turns with it. On the curved peg-in-bore rim contact
// the neglected curvature term makes the comparison inexact: its size is
// measured and bounded. The law's slopes against differences of the law, and
// asking for them changes no bit of the value.
#include "vahf/contact/contact_jacobian.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <vector>

#include "peg_in_bore.h"
#include "support/motion_differences.h"
#include "vahf/contact/penalty_contact.h"
#include "vahf/contact/point_load.h"
#include "vahf/contact/point_shell.h"
#include "vahf/contact/rim.h"
#include "vahf/contact/signed_distance.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {
namespace {

using Eigen::Vector3d;
using geometry::Box;
using geometry::Shape;

const Shape kPart = Box{{0.02, 0.02, 0.01}};      // 20 x 20 x 10 mm
const Shape kPedestal = Box{{0.01, 0.01, 0.01}};  // 10 mm cube

Eigen::Isometry3d At(const Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = t;
  return pose;
}

Obstacle MakeObstacle(const Shape& shape, const Eigen::Isometry3d& pose, bool rims) {
  return Obstacle{SignedDistance(shape), pose, 0.3,
                  geometry::ComputeMassProperties(shape).bounding_radius,
                  rims ? MakeRims(shape, 0.5e-3) : std::vector<RimPoint>{}};
}

// A 1 m x 1 m x 0.2 m floor with its top face the plane z = 0.
Obstacle Floor() { return MakeObstacle(Box{{1.0, 1.0, 0.2}}, At({0, 0, -0.1}), false); }
// The pedestal with its top face the plane z = 0, its edges as rims.
Obstacle Pedestal() { return MakeObstacle(kPedestal, At({0, 0, -0.005}), true); }

enum Sample { kShell = 1, kMovingRim = 2 };
PenaltyContact Model(std::vector<Obstacle> obstacles, int samples, const PenaltyLaw& p) {
  return PenaltyContact(
      samples & kShell ? MakePointShell(kPart, 1e-3) : std::vector<ShellPoint>{},
      SignedDistance(kPart), geometry::ComputeMassProperties(kPart).bounding_radius, 0.5,
      std::move(obstacles), p,
      samples & kMovingRim ? MakeRims(kPart, 0.5e-3) : std::vector<RimPoint>{});
}

// The box's bottom 20 um (centre) into z = 0, off centre and tilted 1 mrad
// about an oblique horizontal axis: its bottom face is 6-34 um deep.
RigidMotion Pressed(bool sliding) {
  RigidMotion m;
  m.pose.linear() =
      Eigen::AngleAxisd(1e-3, Vector3d(1, 2, 0).normalized()).toRotationMatrix();
  m.pose.translation() = Vector3d(1.3e-3, -0.7e-3, 0.005 - 20e-6);
  if (sliding) {  // slip 20-60 mm/s everywhere: Coulomb
    m.velocity = {0.05, 0.02, -0.01};
    m.angular_velocity = {0.2, -0.1, 0.3};
  } else {  // slip under 0.6 mm/s everywhere: below the 1 mm/s transition
    m.velocity = {2e-4, -1e-4, -1e-3};
    m.angular_velocity = {0.01, -0.02, 0.015};
  }
  return m;
}

Eigen::VectorXd Stacked(const ContactForces& f) {
  Eigen::VectorXd out(9);
  out << f.normal_force, f.friction_force, f.torque;
  return out;
}

Eigen::MatrixXd Stacked(const ContactJacobian& j) {
  Eigen::MatrixXd out(9, 12);
  out << j.normal_force, j.friction_force, j.torque;
  return out;
}

// Steps: 1 nm, 0.1 urad (1.4 nm at the box's corners), 0.1 um/s, 10 urad/s.
constexpr std::array<double, 4> kSteps = {1e-9, 1e-7, 1e-7, 1e-5};

struct Compared {
  ContactForces forces;
  Eigen::MatrixXd analytic, differences;
};

Compared Compare(const PenaltyContact& model, const RigidMotion& m) {
  ContactJacobian j;
  Compared out;
  out.forces = model.Evaluate(m, nullptr, &j);
  out.analytic = Stacked(j);
  out.differences = vahf::testing::MotionDifferences(
      [&](const RigidMotion& x) { return Stacked(model.Evaluate(x)); }, m, kSteps);
  // The forces are the same bits as without the derivative.
  EXPECT_EQ(Stacked(out.forces), Stacked(model.Evaluate(m)));
  return out;
}

TEST(ContactJacobian, FaceContactSliding) {
  const PenaltyContact model = Model({Floor()}, kShell, PenaltyLaw());
  const Compared c = Compare(model, Pressed(true));
  ASSERT_GT(c.forces.points_in_contact, 300);
  EXPECT_TRUE(vahf::testing::BlocksAgree(c.analytic, c.differences, 1e-5));
}

TEST(ContactJacobian, FaceContactBelowTheTransitionSpeed) {
  const PenaltyContact model = Model({Floor()}, kShell, PenaltyLaw());
  const Compared c = Compare(model, Pressed(false));
  ASSERT_GT(c.forces.points_in_contact, 300);
  EXPECT_TRUE(vahf::testing::BlocksAgree(c.analytic, c.differences, 1e-5));
}

TEST(ContactJacobian, FaceContactInTheBarrierAndOnItsTangent) {
  for (double barrier : {50e-6, 30e-6}) {  // every point within it; some past b (1 - eps)
    PenaltyLaw p;
    p.barrier_depth = barrier;
    const PenaltyContact model = Model({Floor()}, kShell, p);
    for (bool sliding : {true, false}) {
      const Compared c = Compare(model, Pressed(sliding));
      EXPECT_TRUE(vahf::testing::BlocksAgree(c.analytic, c.differences, 1e-5))
          << barrier << (sliding ? " sliding" : " sticking");
    }
  }
}

TEST(ContactJacobian, MovingRimsInAFlatFloor) {
  PenaltyLaw p;
  p.barrier_depth = 50e-6;
  const PenaltyContact model = Model({Floor()}, kMovingRim, p);
  for (bool sliding : {true, false}) {
    const Compared c = Compare(model, Pressed(sliding));
    ASSERT_GT(c.forces.rim_points_in_contact, 100);
    ASSERT_EQ(c.forces.points_in_contact, 0);
    EXPECT_TRUE(vahf::testing::BlocksAgree(c.analytic, c.differences, 1e-5)) << sliding;
  }
}

TEST(ContactJacobian, FixedRimsInTheMovingFlatFace) {
  for (double barrier : {0.0, 50e-6}) {
    PenaltyLaw p;
    p.barrier_depth = barrier;
    const PenaltyContact model = Model({Pedestal()}, 0, p);
    for (bool sliding : {true, false}) {
      const Compared c = Compare(model, Pressed(sliding));
      ASSERT_GT(c.forces.rim_points_in_contact, 50);
      EXPECT_TRUE(vahf::testing::BlocksAgree(c.analytic, c.differences, 1e-5))
          << barrier << (sliding ? " sliding" : " sticking");
    }
  }
}

TEST(ContactJacobian, EverySampleKindAtOnce) {
  PenaltyLaw p;
  p.barrier_depth = 50e-6;
  const PenaltyContact model = Model({Pedestal()}, kShell | kMovingRim, p);
  const Compared c = Compare(model, Pressed(true));
  ASSERT_GT(c.forces.points_in_contact, 50);
  ASSERT_GT(c.forces.rim_points_in_contact, 50);
  EXPECT_TRUE(vahf::testing::BlocksAgree(c.analytic, c.differences, 1e-5));
}

// The bore's chamfer-to-wall rim 10 um inside the tilted peg's side wall
// (peg_in_bore.h): the peg's normal turns around its 10 mm radius as the rim
// point slides along it, which the Jacobian leaves out.
TEST(ContactJacobian, CurvedRimContactIsCloseButNotExact) {
  using namespace testing;
  PenaltyLaw p;
  p.line_stiffness = 1e7;
  const Obstacle bore = MakeObstacle(ChamferedBore(), At({0, 0, 0}), true);
  const Shape peg = ChamferedPeg();
  const PenaltyContact model(MakePointShell(peg, 1e-3), SignedDistance(peg),
                             geometry::ComputeMassProperties(peg).bounding_radius, 0.5,
                             {bore}, p);
  RigidMotion m;
  m.pose = TiltedPegPose(Vector3d::Zero(), 10e-6);
  m.velocity = {0.01, -0.002, -0.05};
  m.angular_velocity = {0.3, 0.1, -0.2};
  const Compared c = Compare(model, m);
  ASSERT_GT(c.forces.rim_points_in_contact, 0);
  EXPECT_FALSE(vahf::testing::BlocksAgree(c.analytic, c.differences, 1e-5));
  // Measured: the worst block is off by 0.9 % of its size (10 um deep, 10 mm radius).
  const auto result = vahf::testing::BlocksAgree(c.analytic, c.differences, 0.02);
  EXPECT_TRUE(result);
  std::printf("curved rim: %s\n", result.message());
}

// ---------------------------------------------------------------- the law's slopes

TEST(ContactJacobian, LawSlopesAgreeWithDifferencesAndChangeNoBit) {
  PenaltyLaw p;
  p.dissipation = 0.5;
  struct Point {
    double barrier, depth, rate;
  };
  // Onset, linear, inside the barrier, on its tangent (past b (1 - eps)),
  // receding, and the Hunt-Crossley factor clamped at zero.
  for (const Point& q :
       {Point{0, 0.4e-6, 0.1}, Point{0, 5e-6, -0.3}, Point{50e-6, 20e-6, 0.2},
        Point{50e-6, 49.99e-6, 0.2}, Point{50e-6, 49.9e-6, -1.0}, Point{0, 5e-6, -3.0}}) {
    p.barrier_depth = q.barrier;
    LawSlopes s;
    const double value = Pressure(p, q.depth, q.rate, &s);
    EXPECT_EQ(value, Pressure(p, q.depth, q.rate));
    const double hx = 1e-12, hr = 1e-7;
    const double dx =
        (Pressure(p, q.depth + hx, q.rate) - Pressure(p, q.depth - hx, q.rate)) /
        (2 * hx);
    const double dr =
        (Pressure(p, q.depth, q.rate + hr) - Pressure(p, q.depth, q.rate - hr)) /
        (2 * hr);
    EXPECT_NEAR(s.depth, dx, 1e-6 * std::abs(dx) + 1e-3) << q.depth;
    EXPECT_NEAR(s.rate, dr, 1e-6 * std::abs(dr) + 1e-9) << q.depth;
    if (1 + p.dissipation * q.rate < 0) {
      EXPECT_EQ(s.depth, 0.0);
      EXPECT_EQ(s.rate, 0.0);
    }
  }
}

}  // namespace
}  // namespace vahf::contact
