// The derivative of one contact point's loads (its normal force, regularised
// Coulomb friction and their moment about the moving origin, penalty_contact.h)
// with respect to the moving part's motion, in ContactJacobian's columns
// (dx, dtheta, v, w). Summed over the points in contact by PenaltyContact when
// an implicit integrator asks for it.
//
// Exact but for one neglected term: the turning of the field's normal as the
// point moves through it (the field's curvature, its Hessian; zero on a flat
// face). It changes the force's direction by fn / rho per metre, rho the
// radius of curvature, against the penalty's stiffness k A per metre along
// the normal: 1e-3 and less for the scenes' parts (a 0.1 N point force on a
// 10 mm bore, 1e4 N/m a 1 mm^2 point at 1e10 Pa/m). What is kept exactly:
// the depth's and the depth rate's change along the normal, the law's slopes
// (onset, barrier and its tangent, the Hunt-Crossley factor), the friction's
// in both regimes, the lever arm's, and the turning of the moving part's own
// normal with the part for a fixed rim point against the moving field.
#pragma once

#include <Eigen/Core>

#include "vahf/contact/contact_model.h"

namespace vahf::contact {

// Where the contact point sits as the motion changes.
enum class PointFrame {
  // A point of the moving part (shell or moving rim) against a fixed field:
  // it moves and turns with the part; the normal is the fixed field's.
  kMoving,
  // A fixed part's rim point against the moving part's field: it stays put
  // in the world, and the normal (the moving part's) turns with the part.
  kFixed,
};

struct PointContact {
  Eigen::Vector3d r;  // moving origin to the point, world
  Eigen::Vector3d v;  // the moving material's velocity there, world
  Eigen::Vector3d u;  // unit vector along which fn pushes the moving part
  Eigen::Vector3d w;  // the moving part's angular velocity, world
  double fn = 0;      // normal force, N, > 0
  // fn's slopes: per metre of depth and per m/s of depth rate (-v . u).
  double dfn_depth = 0, dfn_rate = 0;
  double mu = 0;                // Coulomb coefficient of the pair
  double transition_speed = 0;  // v_s of the regularised friction, m/s
  PointFrame frame = PointFrame::kMoving;
};

// Adds the point's d(normal force, friction force, torque) to `out`.
void AddPointJacobian(const PointContact& p, ContactJacobian* out);

}  // namespace vahf::contact
