// Closed forms for one Moreau-Jean step (sim/internal/moreau_jean.h), taken
// over and over on bodies meeting a plane z = 0 whose contact points are
// computed exactly at each step: Coulomb's law on an incline (stick below
// arctan(mu), a = g (sin a - mu cos a) above), no creep inside the friction
// cone, Newton's impact law (a dropped ball rises to e^2 H, first order in
// the step), an overlap pushed out over the full step, a ring pressed flat
// that turns at the torque mu F R, a peg in two-point contact that slides
// inside Whitney's jamming diagram and sticks outside it, and the order of
// convergence of the theta-method on a smooth motion.
#include "vahf/sim/internal/moreau_jean.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

namespace vahf::sim::internal {
namespace {

using Eigen::Vector3d;

constexpr double kG = 9.81;

// The points of the body's `corners` (part frame, from its origin) over the
// plane z = 0 within `margin` of it.
std::vector<contact::ContactPoint> PlanePoints(const BodyState& y,
                                               const std::vector<Vector3d>& corners,
                                               double mu, double margin) {
  const Eigen::Quaterniond q(y[3], y[4], y[5], y[6]);
  std::vector<contact::ContactPoint> out;
  for (const Vector3d& c : corners) {
    const Vector3d r = q.normalized() * c;
    const double gap = y[2] + r.z();
    if (gap > margin) continue;
    out.push_back({r, Vector3d::UnitZ(), gap, mu});
  }
  return out;
}

struct Stepping {
  BodyInertia body;
  std::vector<Vector3d> corners;
  double mu = 0.3;
  Vector3d gravity = {0, 0, -kG};
  MoreauJeanSettings settings;
  // Smooth loads at a state (gravity aside); none by default.
  std::function<SmoothLoads(const BodyState&)> loads = [](const BodyState&) {
    return SmoothLoads{};
  };

  // Steps y over `duration` by h; `each` sees every state.
  BodyState Go(BodyState y, double h, double duration,
               const std::function<void(const BodyState&)>& each = nullptr) const {
    const long n = std::lround(duration / h);
    Eigen::VectorXd warm;
    for (long k = 0; k < n; ++k) {
      // The stepper's margin rule: 1.5 times a step's travel at most.
      const double speed = y.segment<3>(7).norm() + 0.1 * y.segment<3>(10).norm() +
                           h * (gravity.norm() + loads(y).force.norm() / body.mass);
      const auto points = PlanePoints(y, corners, mu, std::max(1e-6, 1.5 * h * speed));
      const MoreauJeanStepResult r =
          MoreauJeanStep(body, y, h, loads(y), gravity, points, settings, &warm);
      EXPECT_TRUE(r.solve.converged) << r.solve.detail;
      warm = r.reactions;
      y = r.y;
      if (each) each(y);
    }
    return y;
  }
};

BodyState AtRest(const Vector3d& p) {
  BodyState y = BodyState::Zero();
  y.head<3>() = p;
  y[3] = 1;
  return y;
}

// A 1 kg block, 0.1 m a side, its origin at its centre; its four bottom
// corners on the plane.
Stepping Block(double mu) {
  Stepping run;
  run.body.mass = 1.0;
  run.body.inertia_body = Eigen::Matrix3d::Identity() * (1.0 * 0.01 / 6);
  for (double x : {-0.05, 0.05})
    for (double yy : {-0.05, 0.05}) run.corners.push_back({x, yy, -0.05});
  run.mu = mu;
  return run;
}

// The incline of angle a as gravity tilted by a about y: down the slope is +x.
Vector3d InclineGravity(double a) { return {kG * std::sin(a), 0, -kG * std::cos(a)}; }

TEST(MoreauJean, ABlockOnAnInclineBelowArctanMuDoesNotCreep) {
  for (double theta : {0.5, 1.0}) {
    Stepping run = Block(0.3);
    run.settings.theta = theta;
    run.gravity = InclineGravity(0.95 * std::atan(0.3));
    const BodyState start = AtRest({0, 0, 0.05});
    const BodyState end = run.Go(start, 1e-3, 1.0);
    // Coulomb's law: held inside its cone, the block does not move.
    EXPECT_LT((end.head<3>() - start.head<3>()).norm(), 1e-9) << "theta " << theta;
    EXPECT_LT(end.tail<6>().norm(), 1e-9) << "theta " << theta;
  }
}

TEST(MoreauJean, ABlockOnAnInclineAboveArctanMuSlidesAtTheClosedFormAcceleration) {
  const double mu = 0.3, a = 1.05 * std::atan(mu);
  const double accel = kG * (std::sin(a) - mu * std::cos(a));
  for (double theta : {0.5, 1.0}) {
    Stepping run = Block(mu);
    run.settings.theta = theta;
    run.gravity = InclineGravity(a);
    const double h = 1e-3, t = 1.0;
    const BodyState end = run.Go(AtRest({0, 0, 0.05}), h, t);
    EXPECT_NEAR(end[7], accel * t, 1e-6 * accel * t) << "theta " << theta;
    // Positions by u_theta: exact at theta 1/2, h / t behind at theta 1.
    EXPECT_NEAR(end[0], 0.5 * accel * t * t,
                (theta == 1.0 ? 1.01 * h / t : 1e-6) * 0.5 * accel * t * t)
        << "theta " << theta;
    EXPECT_NEAR(end[2], 0.05, 1e-9);  // on the plane, not into it
  }
}

// A ball of radius 0.02 m, one point under it, dropped from H onto the
// plane: its first rebound peaks at e^2 H.
double FirstRebound(double e, double H, double h) {
  Stepping run;
  run.body.mass = 0.1;
  run.body.inertia_body = Eigen::Matrix3d::Identity() * (0.4 * 0.1 * 0.02 * 0.02);
  run.corners = {{0, 0, -0.02}};
  run.settings.restitution = e;
  double peak = 0;
  bool bounced = false;
  run.Go(AtRest({0, 0, 0.02 + H}), h, 2 * std::sqrt(2 * H / kG), [&](const BodyState& y) {
    if (y[9] > 0) bounced = true;
    if (bounced) peak = std::max(peak, y[2] - 0.02);
  });
  return peak;
}

// The largest error of the rebound over 16 drop heights 0.37 mm apart
// (where the impact falls within a step varies with them): first order, the
// rebound starting from the impact step's start, under h times the speed.
double ReboundError(double e, double h) {
  double worst = 0;
  for (int k = 0; k < 16; ++k) {
    const double H = 0.1 + k * 3.7e-4;
    worst = std::max(worst, std::abs(FirstRebound(e, H, h) - e * e * H));
  }
  return worst;
}

TEST(MoreauJean, ADroppedBallRisesToESquaredHWithAnErrorThatHalvesWithTheStep) {
  const double e = 0.6, H = 0.1;
  const double err1 = ReboundError(e, 2e-3), err2 = ReboundError(e, 1e-3),
               err4 = ReboundError(e, 5e-4);
  EXPECT_LT(err4, 0.02 * e * e * H);
  // First order: each halving of the step about halves the error.
  EXPECT_GT(err1 / err2, 1.6);
  EXPECT_LT(err1 / err2, 2.5);
  EXPECT_GT(err2 / err4, 1.6);
  EXPECT_LT(err2 / err4, 2.5);
}

// An overlap is pushed out over the stepper's full step, also within a step
// the driver has shortened: a ball 1 um into the plane leaves at 1 um over
// the full step, not over the short one.
TEST(MoreauJean, AnOverlapIsPushedOutOverTheFullStep) {
  BodyInertia ball;
  ball.mass = 0.1;
  ball.inertia_body = Eigen::Matrix3d::Identity() * 1.6e-5;
  const BodyState y = AtRest({0, 0, 0.02 - 1e-6});
  const std::vector<contact::ContactPoint> points = {
      {{0, 0, -0.02}, Vector3d::UnitZ(), -1e-6, 0.3}};
  for (const double h : {1e-3, 1e-4, 3.125e-5}) {
    MoreauJeanSettings settings;
    settings.overlap_step = 1e-3;
    const MoreauJeanStepResult r =
        MoreauJeanStep(ball, y, h, {}, Vector3d::Zero(), points, settings);
    EXPECT_NEAR(r.y[9], 1e-6 / 1e-3, 1e-12) << "step " << h;
    // Without a full step to push over, the short step's own.
    settings.overlap_step = 0;
    EXPECT_NEAR(MoreauJeanStep(ball, y, h, {}, Vector3d::Zero(), points, settings).y[9],
                1e-6 / h, 1e-9)
        << "step " << h;
  }
}

// A thin ring of radius R (eight points) pressed flat on the plane by F and
// twisted about its axis by a torque: it stays below mu F R and turns above.
double RingTurn(double torque_fraction) {
  const double R = 0.05, F = 20, mu = 0.2, m = 0.5;
  Stepping run;
  run.body.mass = m;
  run.body.inertia_body = Eigen::Vector3d(0.5, 0.5, 1).asDiagonal() * (m * R * R);
  for (int i = 0; i < 8; ++i)
    run.corners.push_back({R * std::cos(i * M_PI / 4), R * std::sin(i * M_PI / 4), 0});
  run.mu = mu;
  run.gravity = Vector3d::Zero();
  const double torque = torque_fraction * mu * F * R;
  run.loads = [&](const BodyState&) {
    SmoothLoads l;
    l.force = {0, 0, -F};
    l.torque = {0, 0, torque};
    return l;
  };
  const BodyState end = run.Go(AtRest({0, 0, 0}), 1e-3, 0.2);
  return 2 * std::atan2(end.segment<3>(4).norm(), end[3]);  // the angle turned
}

TEST(MoreauJean, ARingPressedFlatTurnsAtMuFRWithinOnePercent) {
  EXPECT_LT(RingTurn(0.99), 1e-9);
  EXPECT_GT(RingTurn(1.01), 1e-4);
}

// Whitney's jamming diagram (D. E. Whitney, "Quasi-static assembly of
// compliantly supported rigid parts", J. Dyn. Syst. Meas. Control 104
// (1982) 65-77): a peg of radius r inserted l deep into its hole, tilted
// against it so that it touches at two points, the hole's edge against the
// peg's side (normal +x on the peg, l above the tip) and the peg's tip
// corner against the far wall (normal -x), both under friction mu. Pushed in
// by f with a side force F_x at the tip and a moment M about it (x right, z
// up, M counterclockwise), the peg is jammed where the two contacts can hold
// that load inside their friction cones, and slides where they cannot: the
// diagram is that set in the plane of (F_x / f, M / (r f)), a parallelogram
// for l > 2 mu r. Its edges here come from the same two-point statics as
// Whitney's equations (1982, Sec. 3), solved by the test directly: with the
// tangential forces T1 = f/2 - d, T2 = f/2 + d (their sum holds f), the
// moment about the tip gives N1 = (M + 2 r d) / l and the side forces
// N2 = F_x + N1, and the load is held if some d puts both contacts inside
// their cones.
struct TwoPointPeg {
  double r = 0.01, l = 0.05, mu = 0.2, f = 10;
  // +1: the hole's edge on the peg's left (-x), the tip on the far (+x)
  // wall; -1: its mirror image, tilted the other way.
  double side = 1;

  // Whether the two contacts can hold the load (the peg tilted as `side`
  // says; the mirror image holds the mirrored load).
  bool Held(double fx, double m) const {
    fx *= side, m *= side;
    // Each condition is linear in d: a + b d >= 0; the d where all hold.
    double lo = -1e300, hi = 1e300;
    const auto need = [&](double a, double b) {
      if (b > 0)
        lo = std::max(lo, -a / b);
      else if (b < 0)
        hi = std::min(hi, -a / b);
      else if (a < 0)
        lo = 1e300;
    };
    // N1 = (m + 2 r d) / l = n0 + n1 d; N2 = fx + N1.
    const double n0 = m / l, n1 = 2 * r / l;
    need(n0, n1);                               // N1 >= 0
    need(fx + n0, n1);                          // N2 >= 0
    need(mu * n0 - f / 2, mu * n1 + 1);         // T1 <= mu N1
    need(mu * n0 + f / 2, mu * n1 - 1);         // -T1 <= mu N1
    need(mu * (fx + n0) - f / 2, mu * n1 - 1);  // T2 <= mu N2
    need(mu * (fx + n0) + f / 2, mu * n1 + 1);  // -T2 <= mu N2
    return lo <= hi;
  }

  // The speed of the peg, at rest, after one Moreau-Jean step under the load.
  double SpeedAfterAStep(double fx, double m) const {
    BodyInertia body;
    body.mass = 0.1;
    body.com = {0, 0, 0.05};
    body.inertia_body = Eigen::Vector3d(1e-4, 1e-4, 5e-6).asDiagonal();
    const std::vector<contact::ContactPoint> points = {
        {{-side * r, 0, l}, side * Vector3d::UnitX(), 0.0, mu},
        {{side * r, 0, 0}, -side * Vector3d::UnitX(), 0.0, mu},
    };
    SmoothLoads loads;
    loads.force = {fx, 0, -f};
    loads.torque = {0, -m, 0};  // counterclockwise in (x, z) is about -y
    const MoreauJeanStepResult step = MoreauJeanStep(body, AtRest(Vector3d::Zero()), 1e-3,
                                                     loads, Vector3d::Zero(), points, {});
    EXPECT_TRUE(step.solve.converged) << step.solve.detail;
    return step.y.tail<6>().norm();
  }

  // How far along the load (fx, m), as a multiple of it, the diagram's edge
  // lies, by bisection from its inside (no load but the push, where the peg
  // slides: l > 2 mu r); 0 when the ray meets no edge within 1000 times.
  double Edge(double fx, double m) const {
    double in = 0, out = 1;
    while (!Held(out * fx, out * m))
      if ((out *= 2) > 1000) return 0;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (in + out);
      (Held(mid * fx, mid * m) ? out : in) = mid;
    }
    return 0.5 * (in + out);
  }
};

TEST(MoreauJean, APegInTwoPointContactSlidesInsideWhitneysJammingDiagram) {
  // Two opposite edges of the diagram: the peg tilted one way and the other.
  // Each is crossed twice, by a side force alone and by a moment alone.
  for (double side : {1.0, -1.0}) {
    TwoPointPeg peg;
    peg.side = side;
    ASSERT_GT(peg.l, 2 * peg.mu * peg.r);
    ASSERT_FALSE(peg.Held(0, 0));  // pushed straight in, it slides
    for (const auto& [fx, m] :
         {std::pair{side * peg.f, 0.0}, std::pair{0.0, side * peg.r * peg.f}}) {
      const double s = peg.Edge(fx, m);
      ASSERT_GT(s, 0) << "side " << side << ", load (" << fx << ", " << m << ")";
      // 5 % inside the edge the peg slides; 5 % outside it is jammed: it does
      // not move at all.
      EXPECT_GT(peg.SpeedAfterAStep(0.95 * s * fx, 0.95 * s * m), 1e-4)
          << "side " << side << ", load (" << fx << ", " << m << ") x " << s;
      EXPECT_LT(peg.SpeedAfterAStep(1.05 * s * fx, 1.05 * s * m), 1e-9)
          << "side " << side << ", load (" << fx << ", " << m << ") x " << s;
    }
  }
}

// A smooth motion: a free body on a spring k x (no contact), the load's
// Jacobian given; the error at t = 1 s against cos(w t) at h and h / 2.
double SpringError(double theta, double h) {
  const double k = 40, m = 1;
  Stepping run;
  run.body.mass = m;
  run.gravity = Vector3d::Zero();
  run.settings.theta = theta;
  run.loads = [&](const BodyState& y) {
    SmoothLoads l;
    l.force = -k * y.head<3>();
    l.jacobian.block<3, 3>(0, 0) = -k * Eigen::Matrix3d::Identity();
    return l;
  };
  const BodyState end = run.Go(AtRest({0.01, 0, 1}), h, 1.0);
  return std::abs(end[0] - 0.01 * std::cos(std::sqrt(k / m) * 1.0));
}

TEST(MoreauJean, TheOrderOnASmoothMotionIsOneAndTwoAtThetaOneHalf) {
  const double order_1 = std::log2(SpringError(1.0, 2e-3) / SpringError(1.0, 1e-3));
  const double order_half = std::log2(SpringError(0.5, 2e-3) / SpringError(0.5, 1e-3));
  EXPECT_GT(order_1, 0.9);
  EXPECT_GT(order_half, 1.9);
}

}  // namespace
}  // namespace vahf::sim::internal
