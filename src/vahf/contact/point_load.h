// The load of one contact point, shared by every penalty contact model
// (docs/design.md decision 7): the normal law, C1 at onset, with its hardening
// barrier and Hunt-Crossley dissipation, and regularised Coulomb friction,
// applied at a point of the moving part; with its derivative when asked.
//
// Normal pressure at penetration depth x (m), rate xdot (m/s):
//   e(x) = k x^2 / (2 x0)          for x < x0   (C1 onset: e(0) = e'(0) = 0)
//   e(x) = k (x - x0 / 2)          for x >= x0  (linear, slope k)
//   p(x) = e(x) / (1 - x / b)^2                 (hardening barrier at depth b)
//   p    *= max(0, 1 + c xdot)                  (Hunt and Crossley, 1975)
// The barrier makes the stiffness rise without bound as the depth nears b, so
// the penetration stays below b under any load the integrator resolves: the
// energy stored by the time x reaches b (1 - eps) grows like k b^2 / eps (an
// inverse-square barrier in the spirit of incremental potential contact: M.
// Li et al., ACM Trans. Graph. 39(4) 49, 2020). Past x_c = b (1 - eps),
// eps = kBarrierReserve, the law continues along its tangent (C1), for a
// trial step that overshoots. b = 0: no barrier, the law stays linear.
// A face point carries the law as a pressure (stiffness, Pa/m) times its
// area; an edge point as a line load (line_stiffness, N/m per m) times the
// length of edge it stands for.
// Friction opposes the moving material's slip velocity v_t at the point:
//   f = -mu |f_n| v_t / max(|v_t|, v_s)        (Coulomb above v_s, linear below)
// with the pair coefficient mu = 2 mu1 mu2 / (mu1 + mu2), the combination
// Simbody's contact forces use (SimTK ContactMaterial, HuntCrossleyForce).
#pragma once

#include <Eigen/Core>

#include "vahf/contact/contact_jacobian.h"
#include "vahf/contact/contact_model.h"
#include "vahf/contact/contact_params.h"

namespace vahf::contact {

// A law's slopes: per metre of depth and per m/s of depth rate.
struct LawSlopes {
  double depth = 0, rate = 0;
};

// The barrier's reserve eps: the law leaves the barrier for its tangent at
// depth b (1 - eps), where it is 1 / eps^2 = 1e6 times the linear law.
inline constexpr double kBarrierReserve = 1e-3;

// The barrier's margin m: a model that resolves a fit with bound b puts its
// barrier at b (1 - m), so that the law's own overshoot past the reserve in a
// hard strike stays within the bound it is checked against. 2 %: 50 times
// the largest overshoot measured, 0.01 um past a 5 um barrier in the resolved
// peg's 1.2 m/s strike on the bore's mouth (docs/physics.md, Contact).
inline constexpr double kBarrierMargin = 0.02;

// The law with stiffness k, onset x0, dissipation c and barrier b; with
// `slopes`, also its derivatives (the value the same bits).
double NormalLaw(double k, double x0, double c, double b, double depth, double depth_rate,
                 LawSlopes* slopes = nullptr);
// The face law (stiffness), Pa, and the edge law (line_stiffness), N/m.
double Pressure(const PenaltyLaw& params, double depth, double depth_rate,
                LawSlopes* slopes = nullptr);
double LineLoad(const PenaltyLaw& params, double depth, double depth_rate,
                LawSlopes* slopes = nullptr);

// The Coulomb coefficient of a pair: 2 a b / (a + b).
double PairFriction(double a, double b);

// One contact point: where it is, how its material moves, the direction it
// pushes the moving part and how deep it is.
struct PointLoad {
  Eigen::Vector3d r;  // moving origin to the point, world
  Eigen::Vector3d v;  // the moving material's velocity there, world
  Eigen::Vector3d u;  // unit vector along which the normal force pushes the moving part
  double depth = 0;   // m
  bool line =
      false;  // an edge point (LineLoad per length) or a face point (Pressure per area)
  double size = 0;  // its length (m) or area (m^2)
  double mu = 0;    // pair Coulomb coefficient
  PointFrame frame = PointFrame::kMoving;
};

// Adds the point's normal force, friction and their moment about the moving
// origin to `out` and, with `jacobian`, their derivative (contact_jacobian.h;
// w the part's angular velocity). False, nothing added, when the normal force
// is not positive.
bool AddPointLoad(const PenaltyLaw& params, const PointLoad& p, const Eigen::Vector3d& w,
                  ContactForces* out, ContactJacobian* jacobian);

}  // namespace vahf::contact
