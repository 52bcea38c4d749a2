// PenaltyContact against closed forms: the pressure law against its defining
// piecewise formula (quadratic onset, linear with slope k beyond, Hunt-Crossley
// factor 1 + c xdot: K. H. Hunt and F. R. E. Crossley, J. Appl. Mech. 42 (1975)
// 440-445); a box pressed flat into a floor against pressure x bottom-face
// area, with Coulomb friction mu N opposing the slip for the harmonic-mean pair
// coefficient mu = 2 mu1 mu2 / (mu1 + mu2) (Simbody's SimTK::ContactMaterial
// combination); a tilted cylinder's rim contact against the integral of the
// pressure over the circular segment of its bottom face that is below the
// floor plus the strip of side wall below it (midpoint rule, 4e5 strips), and
// against itself at finer shell spacings; the broad phase against its
// counters; and the same physical contact described in two frames (rigid-body
// velocity and moment transfer). For rims (a static part's convex edges
// against the moving part's signed distance): their culling against a
// brute-force sum over every rim point, bit for bit, and the peg tilted in the
// bore's mouth described with its origin moved along its axis and in a
// rotated and shifted world. The rim law against closed forms is in
// rim_test.cc.
#include "vahf/contact/penalty_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "peg_in_bore.h"
#include "vahf/contact/point_load.h"
#include "vahf/contact/point_shell.h"
#include "vahf/contact/rim.h"
#include "vahf/contact/signed_distance.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {
namespace {

using geometry::Box;
using geometry::MakeRevolvedProfile;
using geometry::Shape;

constexpr double kMuPart = 0.5, kMuFloor = 0.3;
constexpr double kMu = 2 * kMuPart * kMuFloor / (kMuPart + kMuFloor);  // 0.375

double BoundingRadius(const Shape& s) {
  return geometry::ComputeMassProperties(s).bounding_radius;
}

Obstacle MakeObstacle(const Shape& shape, const Eigen::Isometry3d& pose,
                      double friction) {
  return Obstacle{SignedDistance(shape), pose, friction, BoundingRadius(shape), {}};
}

Eigen::Isometry3d Translation(const Eigen::Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = t;
  return pose;
}

// A 1 m x 1 m x 0.2 m block whose top face is the plane z = 0.
Obstacle Floor() {
  return MakeObstacle(Box{{1.0, 1.0, 0.2}}, Translation({0, 0, -0.1}), kMuFloor);
}

PenaltyContact Model(const Shape& part, double spacing, std::vector<Obstacle> obstacles,
                     const PenaltyLaw& params = PenaltyLaw()) {
  return PenaltyContact(MakePointShell(part, spacing), SignedDistance(part),
                        BoundingRadius(part), kMuPart, std::move(obstacles), params);
}

// ---------------------------------------------------------------- pressure law

TEST(ContactPressure, ZeroWithoutPenetration) {
  const PenaltyLaw p;
  EXPECT_EQ(Pressure(p, 0.0, 0.0), 0.0);
  EXPECT_EQ(Pressure(p, -1e-6, 0.0), 0.0);
  EXPECT_EQ(Pressure(p, -1e-3, 10.0), 0.0);
  EXPECT_EQ(Pressure(p, 0.0, 10.0), 0.0);
}

TEST(ContactPressure, QuadraticOnsetIsC1AtZero) {
  const PenaltyLaw p;
  const double k = p.stiffness, x0 = p.onset_depth;
  for (double x : {1e-9, 1e-8, 1e-7, 5e-7, 0.999e-6})
    EXPECT_NEAR(Pressure(p, x, 0.0), k * x * x / (2 * x0), 1e-12 * k * x0) << x;
  // The value and the forward-difference slope both vanish as the depth does:
  // slope(h) = k h / x0 (1 + 1/2 from the difference) shrinks linearly with h.
  for (double h : {1e-8, 1e-10, 1e-12}) {
    const double value = Pressure(p, h, 0.0);
    const double slope = (Pressure(p, 2 * h, 0.0) - value) / h;
    EXPECT_NEAR(slope, 1.5 * k * h / x0, 1e-6 * k * h / x0) << h;
    EXPECT_LT(slope, 2 * k * h / x0) << h;
    EXPECT_LE(value, k * h * h / x0) << h;
  }
}

TEST(ContactPressure, ContinuousWithSlopeKAtTheOnsetDepthAndLinearBeyond) {
  const PenaltyLaw p;
  const double k = p.stiffness, x0 = p.onset_depth;
  EXPECT_NEAR(Pressure(p, x0, 0.0), k * x0 / 2, 1e-9 * k * x0);
  const double h = 1e-12;
  const double below = Pressure(p, x0 - h, 0.0);
  const double above = Pressure(p, x0 + h, 0.0);
  EXPECT_NEAR(below, k * x0 / 2, 2 * k * h);  // continuous
  EXPECT_NEAR(above, k * x0 / 2, 2 * k * h);
  // One-sided slopes over 1 nm: k (1 - h / (2 x0)) on the left, k on the right.
  const double d = 1e-9;
  const double at = Pressure(p, x0, 0.0);
  EXPECT_NEAR((at - Pressure(p, x0 - d, 0.0)) / d, k, 1e-3 * k);
  EXPECT_NEAR((Pressure(p, x0 + d, 0.0) - at) / d, k, 1e-6 * k);
  // Linear beyond, with slope k and offset x0 / 2.
  for (double x : {2e-6, 1e-5, 1e-4, 1e-3})
    EXPECT_NEAR(Pressure(p, x, 0.0), k * (x - x0 / 2), 1e-12 * k * x) << x;
}

TEST(ContactPressure, HuntCrossleyFactorClampedAtZero) {
  PenaltyLaw p;
  p.dissipation = 0.5;
  for (double x : {5e-7, 2e-5}) {
    const double elastic = Pressure(p, x, 0.0);
    for (double rate : {0.3, 1.0, 10.0, -0.3, -1.0, -1.9})
      EXPECT_NEAR(Pressure(p, x, rate), elastic * (1 + 0.5 * rate), 1e-12 * elastic)
          << "depth " << x << ", rate " << rate;
    // Separating faster than 1/c = 2 m/s: no pull, exactly zero.
    for (double rate : {-2.0, -2.5, -100.0})
      EXPECT_EQ(Pressure(p, x, rate), 0.0) << "rate " << rate;
  }
}

// The hardening barrier (model "resolving"): the elastic law over
// (1 - x/b)^2 up to b (1 - eps), then along its tangent; stiffer without
// bound as x nears b, continuous and C1 where it leaves the barrier.
TEST(ContactPressure, BarrierHardensTowardItsDepthAndLeavesAlongTheTangent) {
  PenaltyLaw plain, barrier;
  plain.dissipation = barrier.dissipation = 0.0;
  const double b = 5e-6;
  barrier.barrier_depth = b;
  for (double x : {0.5e-6, 2e-6, 4e-6, 4.9e-6}) {
    const double s = 1.0 / (1.0 - x / b);
    EXPECT_NEAR(Pressure(barrier, x, 0.0), Pressure(plain, x, 0.0) * s * s,
                1e-12 * Pressure(barrier, x, 0.0))
        << "depth " << x;
  }
  const double xc = b * (1.0 - kBarrierReserve), h = 1e-15;
  const double at = Pressure(barrier, xc, 0.0);
  EXPECT_NEAR(Pressure(barrier, xc + h, 0.0), at, 1e-6 * at);  // continuous
  const double slope_in = (at - Pressure(barrier, xc - 1e-12, 0.0)) / 1e-12;
  const double slope_out = (Pressure(barrier, xc + 1e-12, 0.0) - at) / 1e-12;
  EXPECT_NEAR(slope_out, slope_in, 1e-2 * slope_in);  // C1 at xc
  EXPECT_NEAR(Pressure(barrier, xc + 1e-9, 0.0), at + slope_out * 1e-9,
              1e-6 * at);                         // linear beyond
  EXPECT_GT(at, 1e5 * Pressure(plain, xc, 0.0));  // 1/eps^2 = 1e6 stiffer
}

// ---------------------------------------------------------------- flat box on a floor

// A 40 x 40 x 20 mm box whose bottom face is pressed d into the floor, turned
// about z (still flat) and placed off the floor's centre.
const Eigen::Vector3d kPartSize(0.04, 0.04, 0.02);
constexpr double kBottomArea = 0.04 * 0.04;
constexpr double kDepth = 2e-5;  // 20 x onset_depth

Eigen::Isometry3d FlatPose(double depth) {
  Eigen::Isometry3d pose = Translation({0.1, -0.05, kPartSize.z() / 2 - depth});
  pose.rotate(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  return pose;
}

TEST(ContactModelFlat, NormalForceIsPressureTimesArea) {
  const PenaltyContact model = Model(Box{kPartSize}, 1e-3, {Floor()});
  RigidMotion m;
  m.pose = FlatPose(kDepth);
  const ContactForces f = model.Evaluate(m);
  const double n = Pressure(PenaltyLaw(), kDepth, 0.0) * kBottomArea;
  EXPECT_NEAR(f.normal_force.z() / n, 1.0, 1e-9);
  EXPECT_NEAR(f.normal_force.x(), 0.0, 1e-12 * n);
  EXPECT_NEAR(f.normal_force.y(), 0.0, 1e-12 * n);
  // Uniform pressure on a face centred under the origin: no moment.
  EXPECT_NEAR(f.torque.norm(), 0.0, 1e-9 * n * 0.03);
  EXPECT_EQ(f.friction_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(f.points_in_contact, 40 * 40);
  EXPECT_NEAR(f.max_depth, kDepth, 1e-15);
  EXPECT_TRUE(f.in_contact());
}

TEST(ContactModelFlat, ForceDoesNotDependOnShellSpacing) {
  const double n = Pressure(PenaltyLaw(), kDepth, 0.0) * kBottomArea;
  for (double s : {4e-3, 3e-3, 7e-4}) {
    RigidMotion m;
    m.pose = FlatPose(kDepth);
    const ContactForces f = Model(Box{kPartSize}, s, {Floor()}).Evaluate(m);
    EXPECT_NEAR(f.normal_force.z() / n, 1.0, 1e-9) << "spacing " << s;
  }
}

TEST(ContactModelFlat, HuntCrossleyDampingFromTheApproachSpeed) {
  const PenaltyContact model = Model(Box{kPartSize}, 1e-3, {Floor()});
  RigidMotion m;
  m.pose = FlatPose(kDepth);
  m.velocity = {0, 0, -0.2};  // pressing in at 0.2 m/s: factor 1 + 0.5 * 0.2
  const double n = Pressure(PenaltyLaw(), kDepth, 0.0) * kBottomArea;
  EXPECT_NEAR(model.Evaluate(m).normal_force.z() / n, 1.1, 1e-9);
  m.velocity = {0, 0, 3.0};  // separating faster than 1/c: no force at all
  const ContactForces f = model.Evaluate(m);
  EXPECT_EQ(f.normal_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(f.friction_force, Eigen::Vector3d::Zero());
  EXPECT_FALSE(f.in_contact());
}

TEST(ContactModelFlat, SlidingFrictionIsMuTimesNormalAgainstTheSlip) {
  const PenaltyContact model = Model(Box{kPartSize}, 1e-3, {Floor()});
  const PenaltyLaw params;
  ASSERT_GT(0.05, 10 * params.friction_transition_speed);
  for (double angle : {0.0, 0.8, -2.4}) {
    RigidMotion m;
    m.pose = FlatPose(kDepth);
    const Eigen::Vector3d dir(std::cos(angle), std::sin(angle), 0);
    m.velocity = 0.05 * dir;
    const ContactForces f = model.Evaluate(m);
    const double n = Pressure(params, kDepth, 0.0) * kBottomArea;
    EXPECT_NEAR(f.normal_force.z() / n, 1.0, 1e-9);
    EXPECT_NEAR((f.friction_force - (-kMu * n * dir)).norm(), 0.0, 1e-9 * kMu * n)
        << "friction (" << f.friction_force.transpose() << ")";
    // Friction acts on the bottom face, whose centre is 10 mm under the origin.
    const Eigen::Vector3d moment =
        Eigen::Vector3d(0, 0, -kPartSize.z() / 2).cross(f.friction_force);
    EXPECT_NEAR((f.torque - moment).norm(), 0.0, 1e-9 * n * 0.03);
  }
}

TEST(ContactModelFlat, FrictionIsLinearInSlipBelowTheTransitionSpeed) {
  const PenaltyContact model = Model(Box{kPartSize}, 1e-3, {Floor()});
  const PenaltyLaw params;
  const double vs = params.friction_transition_speed;
  const double n = Pressure(params, kDepth, 0.0) * kBottomArea;
  const Eigen::Vector3d dir(0.6, -0.8, 0);
  for (double speed : {1e-5, 2e-4, 4e-4, 0.999e-3}) {
    RigidMotion m;
    m.pose = FlatPose(kDepth);
    m.velocity = speed * dir;
    const ContactForces f = model.Evaluate(m);
    const Eigen::Vector3d expected = -kMu * n * (speed / vs) * dir;
    EXPECT_NEAR((f.friction_force - expected).norm(), 0.0, 1e-9 * kMu * n)
        << "speed " << speed << ": friction (" << f.friction_force.transpose() << ")";
  }
}

// ---------------------------------------------------------------- tilted peg

constexpr double kPegRadius = 0.01, kPegLength = 0.05;
// A contact: the peg tilted by `tilt` (rad) with its lowest rim point `depth`
// (m) under the floor. The contact patch on the bottom face is depth / sin(tilt)
// wide.
struct TiltedContact {
  double tilt, depth;
};

Shape Peg() {
  return MakeRevolvedProfile(
      {{0, 0}, {kPegRadius, 0}, {kPegRadius, kPegLength}, {0, kPegLength}, {0, 0}});
}

// Tilted by c.tilt about x; the lowest point of the bottom rim, (0, -R, 0) in
// the peg frame, is c.depth under the floor.
Eigen::Isometry3d PegPose(const TiltedContact& c) {
  Eigen::Isometry3d pose =
      Translation({0.01, 0.02, kPegRadius * std::sin(c.tilt) - c.depth});
  pose.rotate(Eigen::AngleAxisd(c.tilt, Eigen::Vector3d::UnitX()));
  return pose;
}

// The continuum normal force, along +z. A bottom-face point (x, y) is
// delta - (y + R) sin(theta) deep, so the face is in contact on the circular
// segment y < -R + delta / sin(theta): the integral of the pressure over it
// (chord 2 sqrt(R^2 - y^2)) by the midpoint rule. A side-wall point at azimuth
// phi and height z is D(phi) - z cos(theta) deep, D = delta - R (1 + sin phi)
// sin(theta), and the model presses it along the floor's normal too, so the wall
// adds the integral over phi of R Q(D) / cos(theta), where
// Q(x) = int_0^x p(u) du = k x^3 / (6 x0) below x0, k x0^2 / 6 + k (x^2 - x0 x) / 2
// beyond (the pressure law integrated once).
double ContinuumPegForce(const PenaltyLaw& params, const TiltedContact& c) {
  const double kTilt = c.tilt, kPegDepth = c.depth;
  const double k = params.stiffness, x0 = params.onset_depth, r = kPegRadius;
  const double a = kPegDepth / std::sin(kTilt);
  const int n = 400000;
  double cap = 0;
  for (int i = 0; i < n; ++i) {
    const double y = -r + (i + 0.5) * a / n;
    const double depth = kPegDepth - (y + r) * std::sin(kTilt);
    cap += 2 * std::sqrt(r * r - y * y) * Pressure(params, depth, 0.0);
  }
  cap *= a / n;
  auto q = [&](double x) {
    return x < x0 ? k * x * x * x / (6 * x0) : k * x0 * x0 / 6 + k * (x * x - x0 * x) / 2;
  };
  double wall = 0;
  for (int i = 0; i < n; ++i) {
    const double phi = -M_PI + (i + 0.5) * M_PI / n;
    const double d = kPegDepth - r * (1 + std::sin(phi)) * std::sin(kTilt);
    if (d > 0) wall += r * q(d) / std::cos(kTilt);
  }
  wall *= M_PI / n;
  std::printf(
      "tilted peg, %.0f um deep: continuum normal force %.6g N (bottom face %.6g N, "
      "side wall %.6g N)\n",
      kPegDepth * 1e6, cap + wall, cap, wall);
  return cap + wall;
}

// Normal force at shell spacings 1, 0.5 and 0.25 mm, printed against the
// continuum value; returns the three forces.
std::vector<double> RefinementSeries(const TiltedContact& c, double* continuum) {
  const PenaltyLaw params;
  *continuum = ContinuumPegForce(params, c);
  std::vector<double> forces;
  for (double s : {1e-3, 0.5e-3, 0.25e-3}) {
    RigidMotion m;
    m.pose = PegPose(c);
    const ContactForces f = Model(Peg(), s, {Floor()}, params).Evaluate(m);
    const double force = f.normal_force.z();
    std::printf(
        "  spacing %.2f mm: normal force %.6g N (%+.2f%% of continuum), "
        "%d points in contact, max depth %.3g um\n",
        s * 1e3, force, 100 * (force / *continuum - 1), f.points_in_contact,
        f.max_depth * 1e6);
    EXPECT_GT(force, 0.0) << "spacing " << s;
    EXPECT_NEAR(f.normal_force.x(), 0.0, 1e-12 * force);
    EXPECT_NEAR(f.normal_force.y(), 0.0, 1e-12 * force);
    forces.push_back(force);
  }
  return forces;
}

TEST(ContactModelPeg, NormalForceConvergesUnderShellRefinement) {
  // Tilted 0.5 deg, 50 um deep: a 5.7 mm wide patch, resolved by a 1 mm shell.
  // Refining the shell twice over changes the force by under 1% each time.
  double continuum = 0;
  const auto f = RefinementSeries({0.5 * M_PI / 180, 50e-6}, &continuum);
  EXPECT_NEAR(f[1] / f[0], 1.0, 0.01);
  EXPECT_NEAR(f[2] / f[1], 1.0, 0.01);
  EXPECT_NEAR(f[2] / continuum, 1.0, 0.01);
}

TEST(ContactModelPeg, PatchNarrowerThanTheShellIsUnderResolved) {
  // A known limit, recorded rather than hidden: tilted 2 deg and 20 um deep
  // the patch is 0.57 mm wide, narrower than the default 1 mm spacing, and the
  // force is far off (-84% at 1 mm); it converges as the spacing falls below
  // the patch width. Edge contacts in a tight bore are like this.
  double continuum = 0;
  const auto f = RefinementSeries({2.0 * M_PI / 180, 20e-6}, &continuum);
  const double e0 = std::abs(f[0] / continuum - 1), e1 = std::abs(f[1] / continuum - 1),
               e2 = std::abs(f[2] / continuum - 1);
  EXPECT_GT(e0, 0.5);  // under-resolved at the default spacing
  EXPECT_LT(e1, e0);
  EXPECT_LT(e2, e1);
  EXPECT_LT(e2, 0.1);
}

// ---------------------------------------------------------------- broad phase

TEST(ContactModelBroadPhase, FarObstacleIsSkippedWithoutPointQueries) {
  const Shape part = Box{kPartSize};
  const Shape block = Box{{0.1, 0.1, 0.1}};
  // Origins 0.5 m apart; the spheres reach 0.03 + 0.0866 m.
  const PenaltyContact model =
      Model(part, 1e-3, {MakeObstacle(block, Translation({0.5, 0, 0}), kMuFloor)});
  RigidMotion m;
  m.velocity = {0.1, 0, -0.1};
  ContactCounters counters;
  const ContactForces f = model.Evaluate(m, &counters);
  EXPECT_EQ(counters.evaluations, 1u);
  EXPECT_EQ(counters.pairs_skipped, 1u);
  EXPECT_EQ(counters.point_queries, 0u);
  EXPECT_EQ(f.normal_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(f.friction_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(f.torque, Eigen::Vector3d::Zero());
  EXPECT_FALSE(f.in_contact());
  model.Evaluate(m, &counters);
  EXPECT_EQ(counters.pairs_skipped, 2u);
  EXPECT_EQ(counters.point_queries, 0u);
}

TEST(ContactModelBroadPhase, FarObstacleDoesNotChangeANearContact) {
  const Shape part = Box{kPartSize};
  const Obstacle far =
      MakeObstacle(Box{{0.1, 0.1, 0.1}}, Translation({0.1, 2.0, 0}), kMuFloor);
  const PenaltyContact alone = Model(part, 1e-3, {Floor()});
  const PenaltyContact both = Model(part, 1e-3, {Floor(), far});
  RigidMotion m;
  m.pose = FlatPose(kDepth);
  m.velocity = {0.02, -0.01, 0};
  ContactCounters alone_counters, both_counters;
  const ContactForces a = alone.Evaluate(m, &alone_counters);
  const ContactForces b = both.Evaluate(m, &both_counters);
  EXPECT_EQ(a.normal_force, b.normal_force);
  EXPECT_EQ(a.friction_force, b.friction_force);
  EXPECT_EQ(a.torque, b.torque);
  EXPECT_EQ(a.points_in_contact, b.points_in_contact);
  EXPECT_EQ(both_counters.pairs_skipped, 1u);  // the far block only
  EXPECT_EQ(alone_counters.pairs_skipped, 0u);
  EXPECT_GT(both_counters.point_queries, 0u);
  EXPECT_LE(both_counters.point_queries, both.shell().size());
}

TEST(ContactModelBroadPhase, ContactAtTheEdgeOfTheBoundingSpheresIsKept) {
  // A 3 m x 3 m floor (bounding radius 2.124 m) whose corner (1.5, 1.5) the box
  // overhangs: a 10 mm x 10 mm square of its bottom face, 1 mm grid, is pressed
  // d into the floor. The origins are 2.138 m apart: outside the floor's sphere,
  // inside the sum of the two radii.
  const Obstacle floor =
      MakeObstacle(Box{{3.0, 3.0, 0.2}}, Translation({0, 0, -0.1}), kMuFloor);
  const PenaltyContact model = Model(Box{kPartSize}, 1e-3, {floor});
  RigidMotion m;
  m.pose = Translation({1.51, 1.51, kPartSize.z() / 2 - kDepth});
  const double apart = (m.pose.translation() - floor.pose.translation()).norm();
  ASSERT_GT(apart, floor.bounding_radius);
  ASSERT_LT(apart, floor.bounding_radius + BoundingRadius(Box{kPartSize}));
  ContactCounters counters;
  const ContactForces f = model.Evaluate(m, &counters);
  EXPECT_EQ(counters.pairs_skipped, 0u);
  EXPECT_EQ(f.points_in_contact, 10 * 10);
  const double n = Pressure(PenaltyLaw(), kDepth, 0.0) * 0.01 * 0.01;
  EXPECT_NEAR(f.normal_force.z() / n, 1.0, 1e-9);
}

TEST(ContactModelBroadPhase, SeparatedButOverlappingSpheresGiveNoForce) {
  // Bounding spheres overlap (origins 0.1 m apart, reach 0.03 + 0.0866 m) but
  // the solids are 5 mm apart.
  const PenaltyContact model =
      Model(Box{kPartSize}, 1e-3,
            {MakeObstacle(Box{{0.1, 0.1, 0.1}}, Translation({0, 0, -0.065}), 0.3)});
  const ContactForces f = model.Evaluate(RigidMotion());
  EXPECT_FALSE(f.in_contact());
  EXPECT_EQ(f.normal_force, Eigen::Vector3d::Zero());
}

TEST(ContactModelBroadPhase, ShellTreeCullsWithoutLosingAContactPoint) {
  // A tilted peg whose rim touches the floor: the sphere tree must skip most of
  // the shell, yet the force must be the sum over every shell point (computed
  // here by brute force with the signed distance and the pressure law).
  const Shape peg = Peg();
  const std::vector<ShellPoint> shell = MakePointShell(peg, 0.5e-3);
  const Obstacle floor = Floor();
  const PenaltyContact model(shell, SignedDistance(peg), BoundingRadius(peg), kMuPart,
                             {floor}, PenaltyLaw());
  RigidMotion m;
  m.pose = PegPose({0.5 * M_PI / 180, 50e-6});  // a 5.7 mm wide patch
  ContactCounters counters;
  const ContactForces f = model.Evaluate(m, &counters);

  Eigen::Vector3d brute = Eigen::Vector3d::Zero();
  int touching = 0;
  const Eigen::Isometry3d to_floor = floor.pose.inverse() * m.pose;
  for (const ShellPoint& p : shell) {
    const Distance d = floor.field.At(to_floor * p.position);
    if (!(d.distance < 0)) continue;
    brute += Pressure(PenaltyLaw(), -d.distance, 0.0) * p.area *
             (floor.pose.linear() * d.normal);
    ++touching;
  }
  ASSERT_GT(touching, 10);
  EXPECT_EQ(f.points_in_contact, touching);
  EXPECT_NEAR((f.normal_force - brute).norm(), 0.0, 1e-12 * brute.norm());
  EXPECT_GT(counters.clusters_skipped, 0u);
  EXPECT_LT(counters.point_queries, shell.size() / 4);
}

// ---------------------------------------------------------------- frame choice

TEST(ContactModelFrame, OriginOffsetFromTheCentroidDoesNotMatter) {
  // Frame A: the peg's own frame (origin at the bottom centre). Frame B: origin
  // at g in A's coordinates, so a point's B coordinates are its A coordinates
  // minus g and pose_B = pose_A * translation(g). B's origin moves with
  // v + w x (R g), and moments about it are tau_A - (R g) x F.
  const Eigen::Vector3d g(0.003, -0.002, 0.025);
  const Shape peg = Peg();
  std::vector<ShellPoint> shell_a = MakePointShell(peg, 0.5e-3), shell_b = shell_a;
  for (ShellPoint& p : shell_b) p.position -= g;
  const double radius_a = BoundingRadius(peg);
  // The floor has no rims, so the moving part's field is never queried here
  // (and frame B's would be the peg's shifted off its axis, which no profile
  // describes); ContactModelFrame.RimContact... below shifts along the axis.
  const PenaltyContact a(shell_a, SignedDistance(peg), radius_a, kMuPart, {Floor()},
                         PenaltyLaw());
  const PenaltyContact b(shell_b, SignedDistance(peg), radius_a + g.norm(), kMuPart,
                         {Floor()}, PenaltyLaw());

  RigidMotion ma;
  ma.pose = PegPose({2.0 * M_PI / 180, 20e-6});
  ma.velocity = {0.0004, -0.02, -0.001};
  ma.angular_velocity = {0.1, -0.2, 0.3};
  RigidMotion mb = ma;
  mb.pose = ma.pose * Translation(g);
  const Eigen::Vector3d rg = ma.pose.linear() * g;
  mb.velocity = ma.velocity + ma.angular_velocity.cross(rg);

  const ContactForces fa = a.Evaluate(ma), fb = b.Evaluate(mb);
  ASSERT_TRUE(fa.in_contact());
  const double scale = fa.normal_force.norm();
  EXPECT_NEAR((fb.normal_force - fa.normal_force).norm(), 0.0, 1e-9 * scale);
  EXPECT_NEAR((fb.friction_force - fa.friction_force).norm(), 0.0, 1e-9 * scale);
  EXPECT_GT(fa.friction_force.norm(), 0.1 * kMu * scale);  // friction is exercised
  const Eigen::Vector3d total = fa.normal_force + fa.friction_force;
  EXPECT_NEAR((fb.torque - (fa.torque - rg.cross(total))).norm(), 0.0,
              1e-9 * scale * 0.05);
  EXPECT_NEAR(fb.max_depth, fa.max_depth, 1e-15);
}

// ---------------------------------------------------------------- rims

// The chamfered bore (peg_in_bore.h) with its rims at 0.5 mm, somewhere on a
// bench, and the peg tilted 2 deg into its mouth with the chamfer-to-wall edge
// 10 um deep in the peg's side, moving towards the wall, down and sideways
// and turning, so that the Hunt-Crossley factor and friction both act.
const Eigen::Vector3d kBoreAt(0.1, -0.2, 0.9);

Obstacle BoreWithRims() {
  Obstacle bore = MakeObstacle(testing::ChamferedBore(), Translation(kBoreAt), kMuFloor);
  bore.rim = MakeRims(testing::ChamferedBore(), kRimSpacing.default_value);
  return bore;
}

RigidMotion TiltedPegMoving() {
  RigidMotion m;
  m.pose = testing::TiltedPegPose(kBoreAt, 10e-6);
  m.velocity = {0.003, 0.01, -0.02};
  m.angular_velocity = {0.1, -0.2, 0.3};
  return m;
}

TEST(ContactModelBroadPhase, RimBlocksCullWithoutChangingABit) {
  // Every rim point visited in order, with the law written out again: the
  // same sums to the last bit, though most blocks are skipped.
  const Shape peg = testing::ChamferedPeg();
  const SignedDistance peg_field(peg);
  const Obstacle bore = BoreWithRims();
  const PenaltyLaw params;
  const PenaltyContact model = Model(peg, 1e-3, {bore}, params);
  const RigidMotion m = TiltedPegMoving();
  ContactCounters c;
  const ContactForces f = model.Evaluate(m, &c);

  ContactForces brute;
  const Eigen::Isometry3d obstacle_in_moving = m.pose.inverse() * bore.pose;
  const Eigen::Matrix3d& rotation = m.pose.linear();
  for (const RimPoint& q : bore.rim) {
    const Eigen::Vector3d p_m = obstacle_in_moving * q.position;
    const Distance d = peg_field.At(p_m);
    if (!(d.distance < 0)) continue;
    const Eigen::Vector3d u = -(rotation * d.normal);
    const Eigen::Vector3d r = rotation * p_m;
    const Eigen::Vector3d v = m.velocity + m.angular_velocity.cross(r);
    const double fn = LineLoad(params, -d.distance, -v.dot(u)) * q.length;
    if (!(fn > 0)) continue;
    const Eigen::Vector3d v_t = v - v.dot(u) * u;
    const Eigen::Vector3d ft =
        -kMu * fn / std::max(v_t.norm(), params.friction_transition_speed) * v_t;
    brute.normal_force += fn * u;
    brute.friction_force += ft;
    brute.torque += r.cross(fn * u + ft);
    ++brute.rim_points_in_contact;
    brute.max_depth = std::max(brute.max_depth, -d.distance);
  }
  ASSERT_GT(brute.rim_points_in_contact, 5);
  EXPECT_EQ(f.points_in_contact, 0);  // the shell misses this edge (rim_test.cc)
  EXPECT_EQ(f.rim_points_in_contact, brute.rim_points_in_contact);
  EXPECT_EQ(f.normal_force, brute.normal_force);
  EXPECT_EQ(f.friction_force, brute.friction_force);
  EXPECT_EQ(f.torque, brute.torque);
  EXPECT_EQ(f.max_depth, brute.max_depth);
  EXPECT_GT(f.friction_force.norm(), 0.5 * kMu * f.normal_force.norm());

  const std::size_t blocks = (bore.rim.size() + PenaltyContact::kRimBlockSize - 1) /
                             PenaltyContact::kRimBlockSize;
  std::printf(
      "peg tilted in the bore mouth: %zu rim points in %zu blocks, %llu queried "
      "(%llu blocks skipped), %llu shell points queried of %zu\n",
      bore.rim.size(), blocks, static_cast<unsigned long long>(c.rim_queries),
      static_cast<unsigned long long>(c.rim_blocks_skipped),
      static_cast<unsigned long long>(c.point_queries), model.shell().size());
  EXPECT_EQ(c.rims_skipped, 0u);
  EXPECT_GT(c.rim_blocks_skipped, blocks / 2);
  // Queried and skipped blocks account for every point.
  EXPECT_GE(c.rim_queries + c.rim_blocks_skipped * PenaltyContact::kRimBlockSize,
            bore.rim.size());
  // The mouth's two circles (139 + 127 points) lie within 50 um of the peg
  // all round, so no sphere about a run of them clears it, and with the peg
  // tilted 2 deg the meridian bounds clear only the runs away from its lean;
  // the outer block's two 30 mm circles (754 points) are skipped but for runs
  // sharing a block with the mouth's.
  EXPECT_LE(c.rim_queries, 139u + 127u + 2 * PenaltyContact::kRimBlockSize);
}

TEST(ContactModelBroadPhase, APegInsideItsBoreIsClearedWithoutPointQueries) {
  // The chamfered peg 20 mm down the bore, its axis 30 um off the bore's and
  // tilted 0.01 deg: every point of its side is within 50 um of the wall, so
  // no bounding sphere about a cluster of its shell or rims clears it, but no
  // point touches (50 um radial clearance). The meridian bounds
  // (sector_bound.h) clear it all.
  const Shape peg = testing::ChamferedPeg();
  const PenaltyContact model(MakePointShell(peg, 1e-3), SignedDistance(peg),
                             BoundingRadius(peg), kMuPart, {BoreWithRims()}, PenaltyLaw(),
                             MakeRims(peg, 0.5e-3));
  RigidMotion m;
  m.pose.linear() =
      Eigen::AngleAxisd(0.01 * M_PI / 180, Eigen::Vector3d::UnitX()).toRotationMatrix();
  m.pose.translation() = kBoreAt + Eigen::Vector3d(30e-6, 0, -0.02);
  ContactCounters c;
  const ContactForces f = model.Evaluate(m, &c);
  EXPECT_FALSE(f.in_contact());
  EXPECT_EQ(c.point_queries, 0u);
  EXPECT_EQ(c.rim_queries, 0u);
  EXPECT_GT(c.clusters_skipped, 0u);
}

TEST(ContactModelBroadPhase, APegAgainstItsBoreWallIsQueriedOnlyNearTheWall) {
  // The peg upright 20 mm down the bore, 55 um off its axis: its side on
  // that side is 5 um into the wall. The force is the brute-force sum over
  // every shell point (no rims here), and only clusters near that side are
  // queried.
  const Shape peg = testing::ChamferedPeg();
  const Obstacle bore =
      MakeObstacle(testing::ChamferedBore(), Translation(kBoreAt), kMuFloor);
  const PenaltyContact model = Model(peg, 1e-3, {bore});
  RigidMotion m;
  m.pose.translation() = kBoreAt + Eigen::Vector3d(0, 55e-6, -0.02);
  ContactCounters c;
  const ContactForces f = model.Evaluate(m, &c);
  const Eigen::Isometry3d to_bore = bore.pose.inverse() * m.pose;
  Eigen::Vector3d brute = Eigen::Vector3d::Zero();
  int touching = 0;
  for (const ShellPoint& p : model.shell()) {
    const Distance d = bore.field.At(to_bore * p.position);
    if (!(d.distance < 0)) continue;
    brute += Pressure(PenaltyLaw(), -d.distance, 0.0) * p.area * d.normal;
    ++touching;
  }
  ASSERT_GT(touching, 100);
  EXPECT_EQ(f.points_in_contact, touching);
  EXPECT_NEAR((f.normal_force - brute).norm(), 0.0, 1e-12 * brute.norm());
  std::printf(
      "peg 55 um off the bore's axis: %d shell points touching, %llu queried of %zu\n",
      touching, static_cast<unsigned long long>(c.point_queries), model.shell().size());
  EXPECT_LT(c.point_queries, 3u * static_cast<unsigned>(touching));
  // Each touching point's distance pass examines every surface edge of the
  // bore's profile (6): the work the trial's contact test budget counts.
  EXPECT_GE(c.edge_tests, 6u * static_cast<unsigned>(touching));
  EXPECT_EQ(c.Tests(), c.point_queries + c.rim_queries + c.edge_tests);
}

TEST(ContactModelBroadPhase, RimsAwayFromTheMovingPartAreSkippedWhole) {
  // A rod 1 m tall (radius 10 mm, origin at its foot, bounding radius 1 m)
  // has rims only at its ends; a 40 mm box 50 mm below its foot is inside the
  // rod's bounding sphere but 0.55 m from the centre of the rims' sphere
  // (radius 0.5 m), beyond the two radii's sum.
  Obstacle rod =
      MakeObstacle(testing::Revolved({{0, 0}, {0.01, 0}, {0.01, 1.0}, {0, 1.0}}),
                   Eigen::Isometry3d::Identity(), kMuFloor);
  rod.rim =
      MakeRims(testing::Revolved({{0, 0}, {0.01, 0}, {0.01, 1.0}, {0, 1.0}}), 0.5e-3);
  const PenaltyContact model = Model(Box{kPartSize}, 1e-3, {rod});
  RigidMotion m;
  m.pose = Translation({0.05, 0, -0.05});
  ContactCounters counters;
  const ContactForces f = model.Evaluate(m, &counters);
  EXPECT_FALSE(f.in_contact());
  EXPECT_EQ(counters.pairs_skipped, 0u);
  EXPECT_EQ(counters.rims_skipped, 1u);
  EXPECT_EQ(counters.rim_queries, 0u);
  EXPECT_EQ(counters.rim_blocks_skipped, 0u);
}

// Rim contact of the tilted peg seen with the peg's origin moved up its axis
// by g (frame B: a point's coordinates are its A coordinates minus g, so its
// profile is A's shifted down by g and pose_B = pose_A * translation(g); B's
// origin moves with v + w x (R g), moments about it are tau_A - (R g) x F).
TEST(ContactModelFrame, RimContactWithTheOriginMovedAlongTheAxis) {
  const double g = 0.025;
  const Shape peg_a = testing::ChamferedPeg();
  std::vector<geometry::ProfilePoint> profile_b =
      std::get<geometry::RevolvedProfile>(peg_a).vertices;
  for (geometry::ProfilePoint& q : profile_b) q.z -= g;
  const Shape peg_b = testing::Revolved(profile_b);
  std::vector<ShellPoint> shell_b = MakePointShell(peg_a, 1e-3);
  for (ShellPoint& p : shell_b) p.position.z() -= g;
  const double radius_a = BoundingRadius(peg_a);
  const PenaltyContact a = Model(peg_a, 1e-3, {BoreWithRims()});
  const PenaltyContact b(shell_b, SignedDistance(peg_b), radius_a + g, kMuPart,
                         {BoreWithRims()}, PenaltyLaw());

  const RigidMotion ma = TiltedPegMoving();
  RigidMotion mb = ma;
  mb.pose = ma.pose * Translation({0, 0, g});
  const Eigen::Vector3d rg = ma.pose.linear() * Eigen::Vector3d(0, 0, g);
  mb.velocity = ma.velocity + ma.angular_velocity.cross(rg);

  const ContactForces fa = a.Evaluate(ma), fb = b.Evaluate(mb);
  ASSERT_GT(fa.rim_points_in_contact, 0);
  EXPECT_EQ(fb.rim_points_in_contact, fa.rim_points_in_contact);
  EXPECT_EQ(fb.points_in_contact, fa.points_in_contact);
  const double scale = fa.normal_force.norm();
  EXPECT_NEAR((fb.normal_force - fa.normal_force).norm(), 0.0, 1e-9 * scale);
  EXPECT_NEAR((fb.friction_force - fa.friction_force).norm(), 0.0, 1e-9 * scale);
  EXPECT_GT(fa.friction_force.norm(), 0.5 * kMu * scale);  // friction is exercised
  const Eigen::Vector3d total = fa.normal_force + fa.friction_force;
  EXPECT_NEAR((fb.torque - (fa.torque - rg.cross(total))).norm(), 0.0,
              1e-9 * scale * 0.05);
  EXPECT_NEAR(fb.max_depth, fa.max_depth, 1e-15);
}

// The same rim contact with the whole scene turned and shifted by W: forces
// and moments turn with it.
TEST(ContactModelFrame, RimContactInATurnedAndShiftedWorld) {
  Eigen::Isometry3d w = Translation({-0.3, 0.7, 0.05});
  w.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()));
  const Shape peg = testing::ChamferedPeg();
  Obstacle turned = BoreWithRims();
  turned.pose = w * turned.pose;
  const PenaltyContact a = Model(peg, 1e-3, {BoreWithRims()});
  const PenaltyContact b = Model(peg, 1e-3, {turned});
  const RigidMotion ma = TiltedPegMoving();
  RigidMotion mb;
  mb.pose = w * ma.pose;
  mb.velocity = w.linear() * ma.velocity;
  mb.angular_velocity = w.linear() * ma.angular_velocity;

  const ContactForces fa = a.Evaluate(ma), fb = b.Evaluate(mb);
  ASSERT_GT(fa.rim_points_in_contact, 0);
  EXPECT_EQ(fb.rim_points_in_contact, fa.rim_points_in_contact);
  const double scale = fa.normal_force.norm();
  EXPECT_NEAR((fb.normal_force - w.linear() * fa.normal_force).norm(), 0.0, 1e-9 * scale);
  EXPECT_NEAR((fb.friction_force - w.linear() * fa.friction_force).norm(), 0.0,
              1e-9 * scale);
  EXPECT_NEAR((fb.torque - w.linear() * fa.torque).norm(), 0.0, 1e-9 * scale * 0.05);
  EXPECT_NEAR(fb.max_depth, fa.max_depth, 1e-15);
}

}  // namespace
}  // namespace vahf::contact
