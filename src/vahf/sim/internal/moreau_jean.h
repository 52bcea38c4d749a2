// One step of Moreau-Jean's nonsmooth time stepping for the free moving body
// (docs/design.md decision 16; docs/physics.md, "Nonsmooth stepping"):
// M. Jean, Comput. Methods Appl. Mech. Engrg. 177 (1999) 235-257; V. Acary
// and B. Brogliato, Numerical Methods for Nonsmooth Dynamical Systems (2008).
// Velocities u = (v_c, w), the centre of mass's velocity and the
// angular velocity, world frame; M = diag(m I, I_w).
//
// The smooth loads f (the operator, gravity, the oil film, the gyroscopic
// term) by the theta-method, the stiff ones implicitly through their
// Jacobian (K in position, C in velocity):
//   W_hat (u+ - u-) = h (f(u-) + h theta K u-) + H^T P,
//   W_hat = M - h theta C - h^2 theta^2 K,
// and the contact impulses P by Coulomb's law, set-valued, at every contact
// point, with Newton's impact law on the normal velocity, in the local
// frame (normal, two tangents) of each point:
//   U = H u+ = W P + q,   W = H W_hat^-1 H^T,   q = H u_free + s,
// P_i in the Coulomb cone of mu_i, U_i + mu_i |U_t,i| e_n in its dual
// (De Saxce's modified velocity), solved by Siconos (frictional_contact.h).
// The shift s on a normal row activates the law by the gap g predicted at
// the step's end (docs/physics.md, "Nonsmooth stepping"), an overlap g < 0
// pushed out over h_o = max(h, overlap_step):
//   closing within the step (g + h U_n- <= 0):  s = e U_n- + min(g, 0) / h_o,
//   otherwise:                                  s = g / h (g >= 0), g / h_o.
// A contact that the step's velocity closes takes Newton's impact law,
// U_n+ >= -e U_n- (the rebound starts from the step's start: first order in
// h, as Moreau's law is); one that it does not close may not be closed by
// the step's change of velocity either, so a resting contact holds its gap.
// An overlap is pushed out over the stepper's full step even when the step
// is shortened: over a step shortened 32-fold after a take-back, pushing two
// opposite overlaps of a wedged part out at once asked 32 times the speed
// and the solver answered with squeezing impulses of 1e3 N s (the piston
// rod, docs/physics.md). Positions follow u_theta = (1 - theta) u- + theta u+.
//
// The normal rows' compliance: W's normal diagonal gains c = delta mean(W_ii)
// (Tikhonov's regularisation, ODE's "constraint force mixing": R. Smith,
// Open Dynamics Engine user guide, Sec. 3.8; C. Lacoursiere, PhD thesis,
// Umea University 2007), so that U_n = (W P + q)_n + c P_n >= 0: a part wedged
// between opposite contacts, whose rigid reactions are not unique (any
// squeeze balances), takes a finite squeeze set by c instead of what the
// solver's iterations drift to (1e7-1e11 N on the piston rod at delta 0;
// docs/physics.md). The rows become soft: a contact gives at c P_n, so
// delta is a model setting (steppers.def), 0 (rigid) unless a scene sets it.
// The tangential rows stay exact: stick is stick.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "vahf/contact/contact_model.h"
#include "vahf/sim/internal/frictional_contact.h"
#include "vahf/sim/rigid_body.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim::internal {

// What the step needs of the body: its mass, and its inertia about its
// centre of mass and that centre, both in the part frame.
struct BodyInertia {
  double mass = 0;
  Eigen::Matrix3d inertia_body = Eigen::Matrix3d::Identity();
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
};

// The smooth loads at the step's start, gravity aside: force at the body
// origin and torque about it (world), and their derivative in
// contact::ContactJacobian's columns (dx, dtheta, v, w) of the origin's
// motion (trial_model.h, LoadJacobian).
struct SmoothLoads {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  LoadJacobian jacobian = LoadJacobian::Zero();
};

struct MoreauJeanSettings {
  double theta = 1.0;         // in [1/2, 1]
  double restitution = 0.0;   // Newton's e, in [0, 1]
  double compliance = 0.0;    // delta, the normal rows' relative compliance (>= 0)
  double overlap_step = 0.0;  // s, the shortest time an overlap is pushed out in
  FrictionalContactOptions solver;
};

struct MoreauJeanStepResult {
  BodyState y;  // at the step's end, its quaternion normalised
  // The step's net contact impulse, N s, world: its normal and tangential
  // parts summed over the points.
  Eigen::Vector3d normal_impulse = Eigen::Vector3d::Zero();
  Eigen::Vector3d friction_impulse = Eigen::Vector3d::Zero();
  int loaded_points = 0;          // points with a normal impulse
  Eigen::VectorXd reactions;      // P, 3 a point (normal, tangent 1, tangent 2)
  FrictionalContactResult solve;  // its report (converged when no point)
};

// The unit tangents t1, t2 of a point's local frame, chosen from its normal
// alone (the same normal, the same bits).
void TangentBasis(const Eigen::Vector3d& normal, Eigen::Vector3d* t1,
                  Eigen::Vector3d* t2);

// One step of size h from y under `loads` and gravity g, with the contact
// points at y (contact::ContactModel::AddContactPoints); `warm`, when given
// and of the points' size, starts the solver. Throws ComputationError when
// Siconos refuses the problem.
MoreauJeanStepResult MoreauJeanStep(const BodyInertia& body, const BodyState& y, double h,
                                    const SmoothLoads& loads,
                                    const Eigen::Vector3d& gravity,
                                    const std::vector<contact::ContactPoint>& points,
                                    const MoreauJeanSettings& settings,
                                    const Eigen::VectorXd* warm = nullptr);

}  // namespace vahf::sim::internal
