#include "vahf/contact/contact_jacobian.h"

#include "vahf/core/cross_matrix.h"

namespace vahf::contact {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Block = ContactJacobian::Block;
using Row = Eigen::Matrix<double, 1, 12>;

// The chain rule through penalty_contact.cc's AddContact and its law. Under
// the columns' motion the part's material at the point moves by
// dx + dtheta x r, so the depth changes by -u . (dx + dtheta x r) for both
// frames (a fixed rim point sinks into the moving field as the part comes
// towards it along its outward normal -u). Then, by frame:
//   moving point: r turns (dr = dtheta x r), v = v_o + w x r turns with it,
//                 u is the fixed field's (curvature neglected);
//   fixed point:  r = x - origin shortens by dx, v = v_o + w x r with it,
//                 u = -R n turns with the part (du = dtheta x u).
void AddPointJacobian(const PointContact& p, ContactJacobian* out) {
  const Matrix3d I = Matrix3d::Identity();
  const Matrix3d r_x = CrossMatrix(p.r), w_x = CrossMatrix(p.w), u_x = CrossMatrix(p.u);
  Block material = Block::Zero(), dr = Block::Zero(), dv = Block::Zero(),
        du = Block::Zero();
  material.block<3, 3>(0, 0) = I;
  material.block<3, 3>(0, 3) = -r_x;
  dv.block<3, 3>(0, 6) = I;     // d v / d v_o
  dv.block<3, 3>(0, 9) = -r_x;  // w x r = -[r]x w
  if (p.frame == PointFrame::kMoving) {
    dr.block<3, 3>(0, 3) = -r_x;        // dtheta x r
    dv.block<3, 3>(0, 3) = -w_x * r_x;  // w x (dtheta x r)
  } else {
    dr.block<3, 3>(0, 0) = -I;
    dv.block<3, 3>(0, 0) = -w_x;  // w x (-dx)
    du.block<3, 3>(0, 3) = -u_x;  // dtheta x u
  }
  // The normal force fn u with fn = law(depth, rate), rate = -v . u.
  const Row depth = -p.u.transpose() * material;
  const Row rate = -p.u.transpose() * dv - p.v.transpose() * du;
  const Row dfn = p.dfn_depth * depth + p.dfn_rate * rate;
  const Block normal = p.u * dfn + p.fn * du;
  // Friction f = -mu fn v_t / max(|v_t|, v_s), v_t = v - (v . u) u.
  const double vu = p.v.dot(p.u);
  const Vector3d vt = p.v - vu * p.u;
  const Block dvt =
      (I - p.u * p.u.transpose()) * dv - p.u * (p.v.transpose() * du) - vu * du;
  const double slip = vt.norm();
  Block friction;
  Vector3d f;
  if (slip < p.transition_speed) {  // linear in the slip ("stick")
    const double g = p.mu / p.transition_speed;
    f = -g * p.fn * vt;
    friction = -g * (vt * dfn + p.fn * dvt);
  } else {  // Coulomb: mu fn against the slip's direction
    const Vector3d t = vt / slip;
    f = -p.mu * p.fn * t;
    friction = -p.mu * (t * dfn + (p.fn / slip) * (I - t * t.transpose()) * dvt);
  }
  // The moment r x (fn u + f).
  const Vector3d force = p.fn * p.u + f;
  out->normal_force += normal;
  out->friction_force += friction;
  out->torque += -CrossMatrix(force) * dr + r_x * (normal + friction);
}

}  // namespace vahf::contact
