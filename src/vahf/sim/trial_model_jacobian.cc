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
  out.topRows<3>() = cj.normal_force + cj.friction_force;
  out.bottomRows<3>() = cj.torque;
  if (!operator_acts) return out;
  const Matrix3d R = m.pose.linear();
  const Vector3d r_grasp = R * part->grasp;
  const Vector3d v_grasp = m.velocity + m.angular_velocity.cross(r_grasp);
  const Matrix3d r_x = CrossMatrix(r_grasp);
  const auto& g = scene->params.guidance;
  const contact::ContactForces& cf = loads.contact;
  const double friction = cf.friction_force.norm();
  const guidance::ImpedancePartials p = guidance::ImpedanceForceJacobian(
      g, d.psi, mass, m.pose.translation(), d.estimated_target, v_grasp,
      {cf.normal_force, friction}, blend_force, part_mass * scene->gravity,
      scene->params.simulation.completion_distance);
  Block dv_grasp = Block::Zero(), dr_grasp = Block::Zero();
  dr_grasp.block<3, 3>(0, 3) = -r_x;  // dtheta x r_g
  dv_grasp.block<3, 3>(0, 3) = -CrossMatrix(m.angular_velocity) * r_x;
  dv_grasp.block<3, 3>(0, 6) = Matrix3d::Identity();
  dv_grasp.block<3, 3>(0, 9) = -r_x;
  Block force = p.velocity * dv_grasp + p.normal_force * cj.normal_force;
  force.block<3, 3>(0, 0) += p.position;
  if (friction > 0)  // |F_f| has no derivative at 0: taken as 0 there
    force += p.friction * (cf.friction_force.transpose() / friction) * cj.friction_force;
  Block torque = -CrossMatrix(loads.assembly_force) * dr_grasp + r_x * force;
  const Matrix3d inertia_world = R * inertia_body * R.transpose();
  const guidance::TorquePartials t = guidance::AssemblyTorqueJacobian(
      g, d.psi, inertia_world, R, d.held_orientation, m.angular_velocity);
  torque.block<3, 3>(0, 3) += t.rotation;
  torque.block<3, 3>(0, 9) += t.omega;
  out.topRows<3>() += force;
  out.bottomRows<3>() += torque;
  return out;
}

}  // namespace vahf::sim
