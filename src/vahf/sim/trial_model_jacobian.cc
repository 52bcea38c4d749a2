// TrialModel::LoadJacobianAt: the chain rule through OperatorLoad
// (trial_model.cc) on top of the contact's own derivative.
#include <Eigen/Geometry>

#include "vahf/core/cross_matrix.h"
#include "vahf/guidance/guidance_jacobian.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Block = contact::ContactJacobian::Block;

// The operator's force F at the grasp r_g = R grasp reads the position, the
// grasp's velocity v_g = v + w x r_g and the contact it feels (the normal
// force vector and the friction's size |F_f|); its torque is r_g x F plus
// the assembly torque, which reads R and w.
LoadJacobian TrialModel::LoadJacobianAt(const contact::RigidMotion& m, const Decision& d,
                                        const Loads& loads,
                                        const contact::ContactJacobian& cj) const {
  LoadJacobian out;
  out.topRows<3>() = cj.normal_force + cj.friction_force + cj.film_force;
  out.bottomRows<3>() = cj.torque;
  if (!operator_acts) return out;
  const Matrix3d R = m.pose.linear();
  const Vector3d r_grasp = R * grasp;
  const auto& g = params.guidance;
  const contact::ContactForces& cf = loads.contact;
  // What the hand feels (OperatorLoad): withdrawing a part, the friction
  // alone, so no derivative through the normal force.
  const Vector3d felt_normal = d.withdraw ? Vector3d::Zero() : Vector3d(cf.normal_force);
  const Block felt_normal_jacobian = d.withdraw ? Block::Zero() : cj.normal_force;
  // The push's point r_c (OperatorLoad): the grasp, or r_grasp + w u with
  // u = R (leading end - grasp) and w the contact blend, whose derivative
  // w' n^T dF_n comes through the contact's.
  Vector3d r_c = r_grasp;
  Eigen::Matrix<double, 1, 12> dw = Eigen::Matrix<double, 1, 12>::Zero();
  Vector3d u = Vector3d::Zero();
  if (compliance_at_leading_end) {
    const double fn = felt_normal.norm();
    u = R * (leading_end - grasp);
    r_c += guidance::ContactBlend(fn, blend_force) * u;
    if (fn > 0)
      dw = guidance::ContactBlendSlope(fn, blend_force) * (felt_normal.transpose() / fn) *
           felt_normal_jacobian;
  }
  const Vector3d v_c = m.velocity + m.angular_velocity.cross(r_c);
  const Matrix3d r_x = CrossMatrix(r_c);
  const double friction = cf.friction_force.norm();
  const guidance::ImpedancePartials p =
      d.withdraw ? guidance::WithdrawalForceJacobian(
                       g, d.Vigour(), mass, m.pose.translation(), d.estimated_target,
                       friction, params.simulation.completion_distance)
                 : guidance::ImpedanceForceJacobian(
                       g, d.Vigour(), mass, m.pose.translation(), d.estimated_target, v_c,
                       {cf.normal_force, friction}, blend_force, part_mass * gravity,
                       params.simulation.completion_distance);
  // dr_c = dtheta x r_c + u dw (u turns with the part: dtheta x (w u) is in
  // the first term); dv_c = dv + dw_ x r_c + w_ x dr_c.
  Block dv_c = Block::Zero(), dr_c = Block::Zero();
  dr_c.block<3, 3>(0, 3) = -r_x;
  dr_c += u * dw;
  dv_c = CrossMatrix(m.angular_velocity) * dr_c;
  dv_c.block<3, 3>(0, 6) += Matrix3d::Identity();
  dv_c.block<3, 3>(0, 9) += -r_x;
  Block force = p.velocity * dv_c + p.normal_force * felt_normal_jacobian;
  force.block<3, 3>(0, 0) += p.position;
  if (friction > 0)  // |F_f| has no derivative at 0: taken as 0 there
    force += p.friction * (cf.friction_force.transpose() / friction) * cj.friction_force;
  // The torque: r_grasp x F at the grasp (F = push - m_h g, the loads'
  // assembly force); r_c x push - r_grasp x (m_h g) otherwise.
  Block torque = r_x * force;
  if (!compliance_at_leading_end) {
    torque += -CrossMatrix(loads.assembly_force) * dr_c;
  } else {
    const Vector3d hand_weight = hand_mass * gravity;
    Block dr_grasp = Block::Zero();
    dr_grasp.block<3, 3>(0, 3) = -CrossMatrix(r_grasp);
    torque += -CrossMatrix(loads.assembly_force + hand_weight) * dr_c +
              CrossMatrix(hand_weight) * dr_grasp;
  }
  const Matrix3d inertia_world = R * torque_inertia_body * R.transpose();
  const guidance::TorquePartials t =
      guidance::AssemblyTorqueJacobian(torque_params, d.Vigour(), inertia_world, R,
                                       d.held_orientation, m.angular_velocity);
  torque.block<3, 3>(0, 3) += t.rotation;
  torque.block<3, 3>(0, 9) += t.omega;
  out.topRows<3>() += force;
  out.bottomRows<3>() += torque;
  return out;
}

}  // namespace vahf::sim
