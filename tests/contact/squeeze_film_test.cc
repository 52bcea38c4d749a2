// The squeeze film of an oiled fit (squeeze_film.h) against what we trust:
// - Reynolds' equation for a long, full, non-rotating film solved here
//   numerically on 20 000 cells (its once-integrated form, no closed form
//   used), at eccentricities up to 0.8, along and across the offset;
// - the textbook limits of a centred film: the short bearing's
//   pi mu R L^3 / c^3 for L << R and the long bearing's 12 pi mu R^3 L / c^3
//   for L >> R;
// - the centred film's resistance to tilting, -C0 phi L^3 / 12 times the
//   tilt rate, and nothing against axial sliding and spin;
// - its Jacobian against central differences.
#include "vahf/contact/squeeze_film.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "support/motion_differences.h"
#include "vahf/contact/contact_registry.h"
#include "vahf/core/error.h"

namespace vahf::contact {
namespace {

using Eigen::Vector3d;
using geometry::RevolvedProfile;

constexpr double kMu = 0.085;  // Pa s, VG 46 at about 25 C
constexpr double kC = 34e-6;   // m, the piston rod's radial clearance
constexpr double kR = 0.0315;  // m, the bore's radius
// The film's radius: the mean of the faces' (to O(c / R) any radius between
// them is the thin film's).
constexpr double kRf = kR - 0.5 * kC;

// A solid rod of radius kR - kC from z = -L/2 to L/2 (its frame), and a bore
// of radius kR from z = -1 to 1 about the world z axis: coaxial at identity.
RevolvedProfile Rod(double length) {
  const double r = kR - kC, h = 0.5 * length;
  return {{{0, -h}, {r, -h}, {r, h}, {0, h}}};
}
RevolvedProfile Bore() { return {{{kR, -1}, {kR + 0.01, -1}, {kR + 0.01, 1}, {kR, 1}}}; }

SqueezeFilm Film(double length, double floor = 1e-12) {
  return SqueezeFilm(FilmFaces(Rod(length), Bore(), Eigen::Isometry3d::Identity()),
                     FilmParams{kMu, floor});
}

// The force per unit length on a long journal offset by e (eps = e / c along
// x) moving laterally at (ex_dot, ey_dot): Reynolds' equation without
// rotation or axial flow, d/dth (h^3 dp/dth) = 12 mu R^2 dh/dt with
// h = c - e cos th, integrated once, h^3 p' = 12 mu R^2 G(th) + K with
// G = int dh/dt, K such that p is periodic, then p and the force
// -int p (cos th, sin th) R dth, all by the trapezoid rule on n cells.
Eigen::Vector2d ReynoldsLongBearing(double eps, double ex_dot, double ey_dot) {
  const int n = 20000;
  const double d = 2 * M_PI / n;
  std::vector<double> th(n + 1), h3(n + 1), g(n + 1);
  for (int i = 0; i <= n; ++i) {
    th[i] = i * d;
    const double h = kC * (1 - eps * std::cos(th[i]));
    h3[i] = h * h * h;
  }
  // dh/dt = -(ex_dot cos th + ey_dot sin th); G its integral from 0.
  g[0] = 0;
  for (int i = 1; i <= n; ++i) {
    const auto dh = [&](int k) {
      return -(ex_dot * std::cos(th[k]) + ey_dot * std::sin(th[k]));
    };
    g[i] = g[i - 1] + 0.5 * d * (dh(i - 1) + dh(i));
  }
  // p' = (A G + K) / h^3, A = 12 mu R^2; periodic p: int p' = 0.
  const double a = 12 * kMu * kRf * kRf;
  double int_g = 0, int_1 = 0;
  for (int i = 0; i < n; ++i) {
    int_g += 0.5 * d * (g[i] / h3[i] + g[i + 1] / h3[i + 1]);
    int_1 += 0.5 * d * (1 / h3[i] + 1 / h3[i + 1]);
  }
  const double k = -a * int_g / int_1;
  std::vector<double> p(n + 1);
  p[0] = 0;
  for (int i = 1; i <= n; ++i)
    p[i] = p[i - 1] + 0.5 * d * ((a * g[i - 1] + k) / h3[i - 1] + (a * g[i] + k) / h3[i]);
  Eigen::Vector2d f = Eigen::Vector2d::Zero();
  for (int i = 0; i < n; ++i)
    f -= 0.5 * d * kRf *
         (p[i] * Eigen::Vector2d(std::cos(th[i]), std::sin(th[i])) +
          p[i + 1] * Eigen::Vector2d(std::cos(th[i + 1]), std::sin(th[i + 1])));
  return f;
}

double Phi(double length) { return length * length / (length * length + 12 * kRf * kRf); }

RigidMotion Offset(double eps, const Vector3d& velocity) {
  RigidMotion m;
  m.pose.translation() = Vector3d(eps * kC, 0, 0);
  m.velocity = velocity;
  return m;
}

TEST(SqueezeFilm, FindsThePistonsFaceAndNotTheWideGap) {
  // The rod of a cylinder: a 34 um fit at the piston, 13 mm of gap along the
  // thin rod, which holds no film.
  const RevolvedProfile rod = {
      {{0, 0}, {kR - kC, 0}, {kR - kC, 0.04}, {0.018, 0.04}, {0.018, 0.37}, {0, 0.37}}};
  const std::vector<FilmFace> faces =
      FilmFaces(rod, Bore(), Eigen::Isometry3d::Identity());
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_NEAR(faces[0].clearance, kC, 1e-12);
  EXPECT_DOUBLE_EQ(faces[0].moving_lo, 0.0);
  EXPECT_DOUBLE_EQ(faces[0].moving_hi, 0.04);
  // Two shafts (or two bores) face no film.
  EXPECT_TRUE(FilmFaces(rod, rod, Eigen::Isometry3d::Identity()).empty());
}

TEST(SqueezeFilm, AgreesWithReynoldsEquationAlongAndAcrossTheOffset) {
  const double length = 0.039;
  const SqueezeFilm film = Film(length);
  for (double eps : {0.0, 0.3, 0.6, 0.8}) {
    for (const Vector3d& v :
         {Vector3d(0.01, 0, 0), Vector3d(0, 0.01, 0), Vector3d(-0.004, 0.007, 0)}) {
      const Eigen::Vector2d reference =
          Phi(length) * length * ReynoldsLongBearing(eps, v.x(), v.y());
      const ContactForces f = film.Evaluate(Offset(eps, v));
      SCOPED_TRACE(::testing::Message() << "eps " << eps << " v " << v.transpose());
      EXPECT_NEAR(f.film_force.x(), reference.x(), 2e-4 * reference.norm());
      EXPECT_NEAR(f.film_force.y(), reference.y(), 2e-4 * reference.norm());
      EXPECT_EQ(f.film_force.z(), 0.0);
      EXPECT_TRUE(f.normal_force.isZero() && f.friction_force.isZero());
      EXPECT_FALSE(f.in_contact());
      // It resists the approach: negative power.
      EXPECT_LT(f.film_force.dot(v), 0.0);
    }
  }
}

TEST(SqueezeFilm, CentredFilmMeetsTheShortAndLongBearingLimits) {
  const double v = 0.01;
  // Short: L = R / 20.
  {
    const double length = kR / 20;
    const double short_bearing = M_PI * kMu * kRf * std::pow(length / kC, 3) * v;
    const ContactForces f = Film(length).Evaluate(Offset(0, Vector3d(v, 0, 0)));
    EXPECT_NEAR(-f.film_force.x(), short_bearing, 1e-3 * short_bearing);
  }
  // Long: L = 60 R.
  {
    const double length = 60 * kR;
    const double long_bearing = 12 * M_PI * kMu * std::pow(kRf / kC, 3) * length * v;
    const ContactForces f = Film(length).Evaluate(Offset(0, Vector3d(v, 0, 0)));
    EXPECT_NEAR(-f.film_force.x(), long_bearing, 5e-3 * long_bearing);
  }
}

TEST(SqueezeFilm, ResistsTiltingButNotSlidingOrSpin) {
  const double length = 0.039, rate = 0.5;  // rad/s
  const SqueezeFilm film = Film(length);
  RigidMotion m;
  m.angular_velocity = Vector3d(rate, 0, 0);
  const ContactForces f = film.Evaluate(m);
  const double c0 = 12 * M_PI * kMu * std::pow(kRf / kC, 3);
  const double expected = -c0 * Phi(length) * std::pow(length, 3) / 12 * rate;
  EXPECT_NEAR(f.torque.x(), expected, 1e-9 * std::abs(expected));
  EXPECT_NEAR(f.film_force.norm(), 0.0, 1e-12 * std::abs(expected) / length);
  // Axial sliding and spin, offset or not: nothing.
  for (double eps : {0.0, 0.5}) {
    RigidMotion slide = Offset(eps, Vector3d(0, 0, 0.3));
    slide.angular_velocity = Vector3d(0, 0, 20);
    const ContactForces s = film.Evaluate(slide);
    EXPECT_EQ(s.film_force.norm(), 0.0);
    EXPECT_EQ(s.torque.norm(), 0.0);
  }
}

TEST(SqueezeFilm, ActsOverTheEngagedLengthOnly) {
  const double length = 0.04;
  const SqueezeFilm film = Film(length);
  // Half of the rod above the bore's mouth at z = 1: engaged length L / 2.
  RigidMotion m = Offset(0, Vector3d(0.01, 0, 0));
  m.pose.translation().z() = 1.0;
  const double half = 0.5 * length;
  const double c0 = 12 * M_PI * kMu * std::pow(kRf / kC, 3);
  const ContactForces f = film.Evaluate(m);
  EXPECT_NEAR(-f.film_force.x(), c0 * Phi(half) * half * 0.01, 1e-9 * c0 * half * 0.01);
  // Wholly out: nothing.
  m.pose.translation().z() = 1.0 + length;
  EXPECT_EQ(film.Evaluate(m).film_force.norm(), 0.0);
}

TEST(SqueezeFilm, TheFloorCapsTheFilmSmoothly) {
  const double floor = 1e-6, ratio = floor / kC;
  const double q_max = (1 - ratio) * (1 - ratio);
  // Within 1 % below 0.85 q_max, never above q_max, rising.
  double last = 0;
  for (double q = 0.01; q < 3; q += 0.01) {
    const double capped = CappedEccentricitySquared(q, ratio);
    if (q < 0.85 * q_max) {
      EXPECT_NEAR(capped, q, 0.01 * q);
    }
    EXPECT_LT(capped, q_max);
    EXPECT_GT(capped, last);
    last = capped;
  }
  // An eccentricity past contact (eps 1.05) gives a finite force.
  const ContactForces f = Film(0.039, floor).Evaluate(Offset(1.05, Vector3d(0.01, 0, 0)));
  EXPECT_TRUE(f.film_force.allFinite());
  EXPECT_LT(f.film_force.x(), 0.0);
}

TEST(SqueezeFilm, JacobianAgreesWithCentralDifferences) {
  const SqueezeFilm film = Film(0.039, 1e-6);
  RigidMotion m;
  m.pose.translation() = Vector3d(12e-6, -9e-6, 0.3);
  m.pose.linear() =
      (Eigen::AngleAxisd(4e-4, Vector3d(1, 0.3, 0).normalized())).toRotationMatrix();
  m.velocity = Vector3d(0.002, -0.001, -0.05);
  m.angular_velocity = Vector3d(0.2, -0.1, 0.4);
  ContactJacobian j;
  const ContactForces f = film.Evaluate(m, nullptr, &j);
  const ContactForces plain = film.Evaluate(m);
  EXPECT_EQ(f.film_force, plain.film_force);  // same bits with or without it
  const auto loads = [&](const RigidMotion& x) {
    const ContactForces g = film.Evaluate(x);
    Eigen::VectorXd out(6);
    out << g.film_force, g.torque;
    return out;
  };
  Eigen::MatrixXd analytic(6, 12);
  analytic << j.film_force, j.torque;
  const Eigen::MatrixXd reference =
      testing::MotionDifferences(loads, m, {1e-9, 1e-7, 1e-6, 1e-5});
  EXPECT_TRUE(testing::BlocksAgree(analytic, reference, 1e-5, 1e-7));
}

TEST(SqueezeFilm, AnOiledSceneAddsTheFilmAndTheLubricatedFriction) {
  const geometry::Shape rod = Rod(0.039), bore = Bore();
  ContactSetup s;
  s.moving = {&rod, Eigen::Isometry3d::Identity(), 0.15, 0.05};
  s.fixed.push_back({&bore, Eigen::Isometry3d::Identity(), 0.15, 1.1});
  s.params.model = "shell";
  const RigidMotion m = Offset(0.5, Vector3d(0.01, 0, 0));
  EXPECT_EQ(BuildContact("shell", s).model->Evaluate(m).film_force.norm(), 0.0);  // dry
  s.params.lubricant_viscosity = kMu;
  const ContactForces oiled = BuildContact("shell", s).model->Evaluate(m);
  const ContactForces film = Film(0.039, s.params.film_floor).Evaluate(m);
  EXPECT_EQ(oiled.film_force, film.film_force);
  EXPECT_LT(oiled.film_force.x(), 0.0);
}

TEST(SqueezeFilm, AFloorAtOrAboveAClearanceIsRefusedNamingTheParameter) {
  const geometry::Shape rod = Rod(0.039), bore = Bore();
  ContactSetup s;
  s.moving = {&rod, Eigen::Isometry3d::Identity(), 0.15, 0.05};
  s.fixed.push_back({&bore, Eigen::Isometry3d::Identity(), 0.15, 1.1});
  s.params.lubricant_viscosity = kMu;
  s.params.film_floor = kC;  // the fit's clearance: no film is left
  try {
    BuildContact("shell", s);
    FAIL() << "a floor at the clearance was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/parameters/contact/film_floor");
    EXPECT_NE(e.rule().find("below the radial clearance"), std::string::npos) << e.rule();
  }
  s.params.film_floor = 0.5 * kC;
  EXPECT_NO_THROW(BuildContact("shell", s));
  s.params.lubricant_viscosity = 0;  // dry: the floor is not read
  s.params.film_floor = 1e-3;
  EXPECT_NO_THROW(BuildContact("shell", s));
}

}  // namespace
}  // namespace vahf::contact
