// Rims (a static part's convex edges) and their line law in PenaltyContact.
//
// MakeRims against closed forms: the samples' total length against the sum of
// the convex edge circles' circumferences 2 pi r (or a box's 4 (a + b + c)),
// the sample counts against ceil(circumference / spacing), every sample on its
// edge; straight, concave and on-axis vertices give none.
//
// The line law against closed forms: a cylinder standing in a bore with radial
// clearance c, pushed sideways by e > c, has the bore mouth's rim circle inside
// it; the rims' force against the integral of line_stiffness * e(depth) times
// the inward normal over the circle (depth in closed form below). A peg tilted
// into a chamfered bore with the bore's chamfer edge 10 um deep in its side, a
// contact the shell alone does not see. The force along sweeps across contact
// onset against the bound the C1 law puts on its change per step.
#include "vahf/contact/rim.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "peg_in_bore.h"
#include "vahf/contact/penalty_contact.h"
#include "vahf/contact/point_shell.h"
#include "vahf/contact/signed_distance.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {
namespace {

using geometry::Box;
using geometry::ProfilePoint;
using geometry::Shape;
using testing::ChamferedBore;
using testing::ChamferedPeg;
using testing::Revolved;

double TotalLength(const std::vector<RimPoint>& rim) {
  double sum = 0;
  for (const RimPoint& q : rim) sum += q.length;
  return sum;
}

int Count(double length, double spacing) {
  return static_cast<int>(std::ceil(length / spacing));
}

// Every sample of `rim` lies on one of the circles (r, z), in order, each
// circle a run of Count(2 pi r, spacing) samples of length 2 pi r / count.
void ExpectCircles(const std::vector<RimPoint>& rim, double spacing,
                   const std::vector<ProfilePoint>& circles) {
  std::size_t k = 0;
  double circumferences = 0;
  for (const ProfilePoint& c : circles) {
    const double circumference = 2 * M_PI * c.r;
    circumferences += circumference;
    const int n = Count(circumference, spacing);
    ASSERT_LE(k + n, rim.size());
    for (int j = 0; j < n; ++j, ++k) {
      const RimPoint& q = rim[k];
      EXPECT_NEAR(std::hypot(q.position.x(), q.position.y()), c.r, 1e-15) << k;
      EXPECT_EQ(q.position.z(), c.z) << k;
      EXPECT_NEAR(q.length, circumference / n, 1e-18) << k;
      EXPECT_LE(q.length, spacing) << k;
    }
  }
  EXPECT_EQ(rim.size(), k);
  // Exact but for the rounding of a sum of a few hundred terms.
  EXPECT_NEAR(TotalLength(rim), circumferences, 1e-12 * circumferences);
}

// ---------------------------------------------------------------- MakeRims

TEST(MakeRims, CylinderHasItsTwoEndCircles) {
  const double r = 0.01, h = 0.05;
  for (double s : {1e-3, 0.5e-3, 0.13e-3}) {
    const auto rim = MakeRims(Revolved({{0, 0}, {r, 0}, {r, h}, {0, h}}), s);
    ExpectCircles(rim, s, {{r, 0}, {r, h}});
  }
  // 2 pi 10 mm / 0.5 mm = 125.66: 126 samples a circle.
  EXPECT_EQ(MakeRims(Revolved({{0, 0}, {r, 0}, {r, h}, {0, h}}), 0.5e-3).size(),
            2u * 126);
}

// The size rule (kMaxRimPoints) is checked against this bound before any rim
// is made: it holds every rim it stands for (it counts concave and straight
// vertices too), and is finite for a 10 m part at 10 um.
TEST(RimSizeBound, HoldsTheRims) {
  for (double s : {1e-3, 0.13e-3}) {
    for (const geometry::Shape& shape :
         {ChamferedBore(), ChamferedPeg(), geometry::Shape{Box{{0.04, 0.03, 0.0173}}}}) {
      const double n = static_cast<double>(MakeRims(shape, s).size());
      EXPECT_GE(RimSizeBound(shape, s), n) << s;
      EXPECT_LE(RimSizeBound(shape, s), 2 * n + 10) << s;
    }
  }
  EXPECT_GT(RimSizeBound(geometry::Shape{Box{{10, 10, 10}}}, 1e-5), 1e6);
}

TEST(MakeRims, ChamferedBoreHasFourCirclesAndNoneAtItsConcaveBottom) {
  // The peg_in_hole scene's bore block: outer bottom and top corners (90 deg),
  // the top face to chamfer and chamfer to wall circles (135 deg each); the
  // bore's bottom corner (r = 10.05 mm, z = -40 mm) is concave (270 deg) and
  // the vertices on the axis are not edges.
  const auto rim = MakeRims(ChamferedBore(), 0.5e-3);
  ExpectCircles(rim, 0.5e-3,
                {{0.03, -0.05}, {0.03, 0.0}, {0.01105, 0.0}, {0.01005, -0.001}});
  for (const RimPoint& q : rim) EXPECT_NE(q.position.z(), -0.04);
}

TEST(MakeRims, ChamferedPegHasThreeCircles) {
  const auto rim = MakeRims(ChamferedPeg(), 1e-3);
  ExpectCircles(rim, 1e-3, {{0.0095, 0}, {0.01, 0.0005}, {0.01, 0.05}});
}

TEST(MakeRims, StraightAndNearlyStraightVerticesGiveNone) {
  // The side wall split at mid height (exactly straight), and a wall bent by
  // 0.5 deg (interior angle 179.5 deg, blunter than the 179 deg limit): only
  // the two end circles. Bent by 2 deg: a third circle at the bend.
  const double r = 0.01, h = 0.04;
  const double s = 1e-3;
  const auto straight =
      MakeRims(Revolved({{0, 0}, {r, 0}, {r, h / 2}, {r, h}, {0, h}}), s);
  ExpectCircles(straight, s, {{r, 0}, {r, h}});
  // The upper half leans inwards by `bend`: the vertex at mid height turns left.
  const auto bent = [&](double bend_deg) {
    const double top_r = r - (h / 2) * std::tan(bend_deg * M_PI / 180);
    return MakeRims(Revolved({{0, 0}, {r, 0}, {r, h / 2}, {top_r, h}, {0, h}}), s);
  };
  const double blunt_top = r - (h / 2) * std::tan(0.5 * M_PI / 180);
  ExpectCircles(bent(0.5), s, {{r, 0}, {blunt_top, h}});
  const double sharp_top = r - (h / 2) * std::tan(2.0 * M_PI / 180);
  ExpectCircles(bent(2.0), s, {{r, 0}, {r, h / 2}, {sharp_top, h}});
}

TEST(MakeRims, ConeHasOnlyItsBaseCircle) {
  // The apex lies on the axis: no circle there.
  const auto rim = MakeRims(Revolved({{0, 0}, {0.02, 0}, {0, 0.03}}), 1e-3);
  ExpectCircles(rim, 1e-3, {{0.02, 0}});
}

TEST(MakeRims, GroovedTubeHasNoCircleAtTheGrooveBottom) {
  // A tube (inner radius 5 mm, outer 10 mm) has four convex end circles; a
  // rectangular groove cut 2 mm into its outer wall adds its two lips (convex,
  // 90 deg) but not its bottom corners (concave, 270 deg).
  const auto rim = MakeRims(Revolved({{0.005, 0},
                                      {0.01, 0},
                                      {0.01, 0.01},
                                      {0.008, 0.01},
                                      {0.008, 0.012},
                                      {0.01, 0.012},
                                      {0.01, 0.02},
                                      {0.005, 0.02}}),
                            1e-3);
  ExpectCircles(
      rim, 1e-3,
      {{0.005, 0}, {0.01, 0}, {0.01, 0.01}, {0.01, 0.012}, {0.01, 0.02}, {0.005, 0.02}});
  for (const RimPoint& q : rim)
    EXPECT_GT(std::abs(std::hypot(q.position.x(), q.position.y()) - 0.008), 1e-3);
}

TEST(MakeRims, BoxHasTwelveEdgesSampledAtSegmentMidpoints) {
  const Eigen::Vector3d size(0.04, 0.01, 0.023);
  const double s = 1e-3;
  const auto rim = MakeRims(Box{size}, s);
  // 10 mm at 1 mm is exactly 10 samples, though 0.01 / 0.001 rounds above 10.
  const int nx = 40, ny = 10, nz = 23;
  ASSERT_EQ(rim.size(), static_cast<std::size_t>(4 * (nx + ny + nz)));
  EXPECT_NEAR(TotalLength(rim), 4 * size.sum(), 1e-15);
  const SignedDistance field{Box{size}};
  for (const RimPoint& q : rim) {
    // On exactly two faces, inside the third pair, at a segment midpoint.
    int on_faces = 0, along = -1;
    for (int a = 0; a < 3; ++a) {
      if (std::abs(q.position[a]) == size[a] / 2)
        ++on_faces;
      else
        along = a;
    }
    ASSERT_EQ(on_faces, 2);
    const int n = along == 0 ? nx : along == 1 ? ny : nz;
    const double i = (q.position[along] + size[along] / 2) / q.length - 0.5;
    EXPECT_NEAR(i, std::round(i), 1e-9);
    EXPECT_NEAR(q.length, size[along] / n, 1e-18);
    EXPECT_NEAR(field.At(q.position).distance, 0.0, 1e-15);
  }
}

TEST(MakeRims, SamplesLieOnTheSurface) {
  const SignedDistance field(ChamferedBore());
  for (const RimPoint& q : MakeRims(ChamferedBore(), 0.5e-3))
    EXPECT_NEAR(field.At(q.position).distance, 0.0, 1e-15);
}

// ---------------------------------------------------------------- line law

constexpr double kMuPart = 0.15, kMuBore = 0.15;

double BoundingRadius(const Shape& s) {
  return geometry::ComputeMassProperties(s).bounding_radius;
}

Eigen::Isometry3d Translation(const Eigen::Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = t;
  return pose;
}

Obstacle WithRims(const Shape& shape, const Eigen::Isometry3d& pose, double rim_spacing) {
  return Obstacle{SignedDistance(shape), pose, kMuBore, BoundingRadius(shape),
                  MakeRims(shape, rim_spacing)};
}

PenaltyContact Model(const Shape& part, std::vector<Obstacle> obstacles,
                     const PenaltyLaw& params = PenaltyLaw()) {
  return PenaltyContact(MakePointShell(part, ContactParams().shell_spacing),
                        SignedDistance(part), BoundingRadius(part), kMuPart,
                        std::move(obstacles), params);
}

// The C1 onset shape of both laws: x^2 / (2 x0), then x - x0 / 2; and its slope.
double Onset(double x, double x0) {
  return x <= 0 ? 0.0 : x < x0 ? x * x / (2 * x0) : x - x0 / 2;
}
double OnsetSlope(double x, double x0) { return std::clamp(x / x0, 0.0, 1.0); }

// Cylinder in a plain bore (no chamfer): radius R, bore radius Rb = R + c, the
// bore's mouth at z = 0 of the bore frame, the bore block 30 mm in radius.
constexpr double kR = 0.01, kClearance = 50e-6, kRb = kR + kClearance;
const Eigen::Vector3d kBoreAt(0.1, -0.2, 0.9);

Shape Cylinder() { return Revolved({{0, 0}, {kR, 0}, {kR, 0.05}, {0, 0.05}}); }
Shape PlainBore() {
  return Revolved(
      {{0, -0.05}, {0.03, -0.05}, {0.03, 0}, {kRb, 0}, {kRb, -0.04}, {0, -0.04}});
}
// The cylinder's axis offset by `offset` along x from the bore's, its bottom
// 20 mm down the bore.
Eigen::Isometry3d CylinderPose(double offset) {
  return Translation(kBoreAt + Eigen::Vector3d(offset, 0, -0.02));
}

// The rims' force on the cylinder, offset e: the mouth circle's point at
// azimuth phi, (Rb cos phi, Rb sin phi, 0) in the bore frame, is at
// (Rb cos phi - e, Rb sin phi) across the cylinder's axis, at
// rho = sqrt(Rb^2 + e^2 - 2 Rb e cos phi) from it, and R - rho deep in it (the
// side wall is the nearest surface: the mouth is 20 mm above the bottom and 30
// below the top). The cylinder's outward normal there is the unit vector
// (Rb cos phi - e, Rb sin phi, 0) / rho, and the rim pushes against it, so
//   F = -int_0^{2 pi} k_l e(R - rho) (Rb cos phi - e, Rb sin phi, 0) / rho Rb dphi
// (midpoint rule, 2e6 steps; the y part vanishes by symmetry).
Eigen::Vector3d MouthRimForce(const PenaltyLaw& p, double e) {
  const int n = 2000000;
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * (i + 0.5) / n;
    const double x = kRb * std::cos(phi) - e, y = kRb * std::sin(phi);
    const double rho = std::hypot(x, y);
    f -= p.line_stiffness * Onset(kR - rho, p.onset_depth) * Eigen::Vector3d(x, y, 0) /
         rho * kRb;
  }
  return f * (2 * M_PI / n);
}

TEST(RimContact, BoreMouthInAnOffsetCylinderAgainstTheClosedForm) {
  // e = 80 um > c = 50 um: the mouth rim is up to 30 um deep over +-0.89 rad.
  const double e = 80e-6;
  PenaltyLaw params;
  const Eigen::Vector3d expected = MouthRimForce(params, e);
  std::printf("cylinder offset %.0f um in a %.0f um clearance: rim force %.6g N\n",
              e * 1e6, kClearance * 1e6, expected.x());
  RigidMotion m;
  m.pose = CylinderPose(e);
  for (double s : {1e-3, 0.5e-3, 0.25e-3, 0.1e-3}) {
    Obstacle bore = WithRims(PlainBore(), Translation(kBoreAt), s);
    Obstacle bare = bore;
    bare.rim.clear();
    const ContactForces with = Model(Cylinder(), {bore}, params).Evaluate(m);
    const ContactForces without = Model(Cylinder(), {bare}, params).Evaluate(m);
    // The shell's share is unchanged: the rims add to it.
    EXPECT_EQ(with.points_in_contact, without.points_in_contact);
    EXPECT_GT(without.points_in_contact, 0);
    EXPECT_EQ(without.rim_points_in_contact, 0);
    const Eigen::Vector3d f = with.normal_force - without.normal_force;
    const Eigen::Vector3d tau = with.torque - without.torque;
    std::printf(
        "  rim spacing %.2f mm: %d rim points, force %.6g N (%+.3f%%), "
        "max depth %.3f um\n",
        s * 1e3, with.rim_points_in_contact, f.x(), 100 * (f.x() / expected.x() - 1),
        with.max_depth * 1e6);
    EXPECT_NEAR(f.x() / expected.x(), 1.0, 0.01) << "spacing " << s;
    EXPECT_NEAR(f.y(), 0.0, 1e-9 * f.norm()) << "spacing " << s;
    EXPECT_NEAR(f.z(), 0.0, 1e-9 * f.norm()) << "spacing " << s;
    // Radial forces at 20 mm above the origin: torque 0.02 z x F.
    EXPECT_NEAR((tau - Eigen::Vector3d(0, 0, 0.02).cross(f)).norm(), 0.0,
                1e-9 * f.norm() * 0.02)
        << "spacing " << s;
    // No velocity: no friction.
    EXPECT_EQ(with.friction_force, Eigen::Vector3d::Zero());
    // The deepest sample is within half a spacing of azimuth 0.
    EXPECT_LE(with.max_depth, e - kClearance);
    EXPECT_GT(with.max_depth, 0.99 * (e - kClearance));
  }
}

TEST(RimContact, NoRimForceWithinTheClearance) {
  RigidMotion m;
  m.pose = CylinderPose(0.99 * kClearance);
  const ContactForces f =
      Model(Cylinder(), {WithRims(PlainBore(), Translation(kBoreAt), 0.5e-3)})
          .Evaluate(m);
  EXPECT_FALSE(f.in_contact());
  EXPECT_EQ(f.normal_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(f.max_depth, 0.0);
}

Eigen::Isometry3d TiltedPegPose(double depth) {
  return testing::TiltedPegPose(kBoreAt, depth);
}

TEST(RimContact, TiltedPegSeesTheBoreEdgeTheShellMisses) {
  const double depth = 10e-6;
  Obstacle bore = WithRims(ChamferedBore(), Translation(kBoreAt), 0.5e-3);
  Obstacle bare = bore;
  bare.rim.clear();
  RigidMotion m;
  m.pose = TiltedPegPose(depth);
  const ContactForces shell_only = Model(ChamferedPeg(), {bare}).Evaluate(m);
  const ContactForces with = Model(ChamferedPeg(), {bore}).Evaluate(m);
  // An exact check: the deepest point of the chamfer-to-wall circle in the
  // peg, over 1e5 points.
  const SignedDistance peg(ChamferedPeg());
  double deepest = 0;
  for (int i = 0; i < 100000; ++i) {
    const double phi = 2 * M_PI * i / 100000;
    const Eigen::Vector3d w =
        kBoreAt + Eigen::Vector3d(testing::kBoreRadius * std::cos(phi),
                                  testing::kBoreRadius * std::sin(phi), -0.001);
    deepest = std::max(deepest, -peg.At(m.pose.inverse() * w).distance);
  }
  std::printf(
      "peg tilted 2 deg: bore edge %.3f um deep in it (exact), shell alone "
      "%d points, with rims %d rim points, max depth %.3f um, force (%.4g, %.4g, "
      "%.4g) N\n",
      deepest * 1e6, shell_only.points_in_contact, with.rim_points_in_contact,
      with.max_depth * 1e6, with.normal_force.x(), with.normal_force.y(),
      with.normal_force.z());
  EXPECT_NEAR(deepest, depth, 0.05 * depth);
  EXPECT_FALSE(shell_only.in_contact());
  EXPECT_EQ(shell_only.max_depth, 0.0);
  EXPECT_EQ(with.points_in_contact, 0);
  EXPECT_GT(with.rim_points_in_contact, 0);
  EXPECT_LE(with.max_depth, deepest);
  EXPECT_GT(with.max_depth, 0.99 * deepest);
  // Pushed off the wall (-y) and, against the side wall's normal
  // (0, cos 2 deg, -sin 2 deg) at every point, a little up: z / y = -tan 2 deg.
  EXPECT_LT(with.normal_force.y(), 0.0);
  EXPECT_NEAR(with.normal_force.z() / with.normal_force.y(), -std::tan(testing::kTiltRad),
              1e-9);
  // Across the tilt plane only what the odd sample count (127) leaves.
  EXPECT_LT(std::abs(with.normal_force.x()), 1e-3 * with.normal_force.norm());
}

// ---------------------------------------------------------------- continuity

// Sweeps the moving part along `direction` (unit) in steps h = x0 / 50 and
// checks each step's force change against what the C1 law allows. A step
// moves every contact point by h relative to the part, so each depth changes
// by at most h and each point's force K w e(x) (K w: stiffness times area or
// length) by at most K w e'(X + h) h, X the deepest before or after, while its
// direction, the normal of a wall of radius >= rho_min, turns by at most
// h / rho_min. A jump at onset (a law with e(0+) > 0) or a kink (e'(0+) > 0)
// breaks the bound where the first point touches.
void SweepAcrossOnset(const Shape& part, const Obstacle& obstacle,
                      const Eigen::Isometry3d& start, const Eigen::Vector3d& direction,
                      int steps, double rho_min, double max_shell_area) {
  const PenaltyLaw params;
  const PenaltyContact model = Model(part, {obstacle}, params);
  double max_rim_length = 0;
  for (const RimPoint& q : obstacle.rim)
    max_rim_length = std::max(max_rim_length, q.length);
  const double x0 = params.onset_depth, h = x0 / 50;
  const double k_shell = params.stiffness * max_shell_area;
  const double k_rim = params.line_stiffness * max_rim_length;
  RigidMotion m;
  m.pose = start;
  ContactForces before = model.Evaluate(m);
  ASSERT_FALSE(before.in_contact());
  int first = -1;
  double worst = 0;  // largest change / bound
  for (int i = 1; i <= steps; ++i) {
    m.pose.translation() += h * direction;
    const ContactForces after = model.Evaluate(m);
    const double x = std::max(before.max_depth, after.max_depth);
    const double per_point = OnsetSlope(x + h, x0) * h + Onset(x, x0) * h / rho_min;
    const double bound =
        (k_shell * (before.points_in_contact + after.points_in_contact) +
         k_rim * (before.rim_points_in_contact + after.rim_points_in_contact)) *
        per_point;
    const double change = (after.normal_force - before.normal_force).norm();
    EXPECT_LE(change, bound) << "step " << i;
    if (bound > 0) worst = std::max(worst, change / bound);
    if (first < 0 && after.in_contact()) {
      first = i;
      // Nothing touched a step ago, so nothing is deeper than h now.
      EXPECT_LE(after.max_depth, h);
      EXPECT_LE(after.normal_force.norm(), (k_shell * after.points_in_contact +
                                            k_rim * after.rim_points_in_contact) *
                                               h * h / (2 * x0));
    }
    before = after;
  }
  ASSERT_GT(first, 0) << "never touched";
  EXPECT_GT(before.max_depth, 2 * x0);  // swept well past the onset
  std::printf(
      "  first contact at step %d of %d, final depth %.3f um, %d shell + %d rim "
      "points, largest change %.3f of the bound\n",
      first, steps, before.max_depth * 1e6, before.points_in_contact,
      before.rim_points_in_contact, worst);
}

TEST(RimContact, ForceIsContinuousAcrossOnsetForTheTiltedPeg) {
  // From 1 um clear of the bore's edge to 3 um into it, towards the wall.
  const Obstacle bore = WithRims(ChamferedBore(), Translation(kBoreAt), 0.5e-3);
  SweepAcrossOnset(ChamferedPeg(), bore, TiltedPegPose(-1e-6), Eigen::Vector3d::UnitY(),
                   200, 0.009, 0.0);
}

TEST(RimContact, ForceIsContinuousAcrossOnsetForTheOffsetCylinder) {
  // Shell points on the side wall and the mouth rim touch together at e = c:
  // from 1 um short of it to 3 um past. The largest shell patch is an end
  // face's outer ring (under 1 mm^2).
  const Obstacle bore = WithRims(PlainBore(), Translation(kBoreAt), 0.5e-3);
  double max_area = 0;
  for (const ShellPoint& s : MakePointShell(Cylinder(), 1e-3))
    max_area = std::max(max_area, s.area);
  SweepAcrossOnset(Cylinder(), bore, CylinderPose(kClearance - 1e-6),
                   Eigen::Vector3d::UnitX(), 200, 0.009, max_area);
}

}  // namespace
}  // namespace vahf::contact
