// One part of a scene as every trial of it sees it, without Simbody
// (docs/design.md decision 13): the moving body (part and hand), the operator's
// posture and factor curves, the contact model, the visibility meshes, the
// penetration bound; and the two force elements besides gravity, the contact
// and the operator, as functions of the part's motion and the operator's held
// decision, which any stepper can evaluate.
//
// Built and checked once per part and experiment (BuildTrialModel), then
// shared, read-only but for its pool of visibility casters, by every trial of
// that part on every thread.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "vahf/contact/contact_model.h"
#include "vahf/contact/contact_registry.h"
#include "vahf/geometry/tessellation.h"
#include "vahf/human/factors.h"
#include "vahf/scene/scene.h"
#include "vahf/visibility/caster_pool.h"

namespace vahf::sim {

struct PhaseSeconds;  // phase_seconds.h

// What the operator decided at the last decision instant, held until the next
// (docs/design.md decision 1). The contact it met is not held: the force law
// reads the current contact (guidance::ImpedanceForce), so the force is
// continuous in the state.
struct Decision {
  Eigen::Vector3d estimated_target = Eigen::Vector3d::Zero();  // T' of Eq. 5
  Eigen::Matrix3d held_orientation = Eigen::Matrix3d::Identity();
  double psi = 1.0;
  // The practice gain G(n) of the trial's repetition (human/learning.h):
  // the force and torque laws take Psi G(n) where Eq. 5 takes Psi.
  double practice_gain = 1.0;
  // The operator withdraws a stopped part (GuidanceParams::stall_time): the
  // force is guidance::WithdrawalForce towards estimated_target, which feels
  // the contact's friction but not its normal.
  bool withdraw = false;
  // Psi as the operator's force and torque laws take it.
  double Vigour() const { return psi * practice_gain; }
};

// The loads on the moving body at one state, world frame.
struct Loads {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // at the body origin, N
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // about the body origin, N m
  // The operator's, at the grasp.
  Eigen::Vector3d assembly_force = Eigen::Vector3d::Zero();
  contact::ContactForces contact;
};

// The derivative of the loads' force (rows 0-2) and torque about the origin
// (rows 3-5) with respect to the part's motion, in contact::ContactJacobian's
// columns (dx, dtheta, v, w): for implicit steppers.
using LoadJacobian = Eigen::Matrix<double, 6, 12>;

struct TrialModel {
  explicit TrialModel(human::FactorCurves factor_curves)
      : curves(std::move(factor_curves)) {}

  // What a trial reads of its scene, copied in when the model is built: the
  // model holds no pointer into its input, and its modes are resolved once.
  scene::Parameters params;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // m/s^2, world
  std::string part_name;
  scene::Pose initial;  // the part's pose at the start of its trial, world
  scene::Pose target;   // and where it is assembled
  Eigen::Vector3d grasp = Eigen::Vector3d::Zero();  // where the hand holds it, part frame
  enum class Visibility { kOff, kConstant, kRaycast };  // visibility/mode
  Visibility visibility_mode = Visibility::kOff;
  int sequence_position = 0;
  bool operator_acts = true;  // guidance mode "operator"
  // The moving body: the part, plus the operator's hand and forearm as a point
  // mass at the grasp point (guidance/hand_mass) when an operator guides it.
  double part_mass = 0;
  double hand_mass = 0;
  double mass = 0;  // part + hand
  // Of both, about their centre of mass, part frame.
  Eigen::Matrix3d inertia_body = Eigen::Matrix3d::Zero();
  Eigen::Vector3d com = Eigen::Vector3d::Zero();  // of both, part frame
  // Of the part alone: where factors look.
  Eigen::Vector3d part_com = Eigen::Vector3d::Zero();
  bool revolved = false;  // orientation about the part's own z axis is free
  // The part's bounding radius about its frame origin, m: what an angle turns
  // into a displacement at its farthest point (CVODE's error weights).
  double bounding_radius = 0;
  human::Posture posture;
  human::FactorCurves curves;
  double reach_limit = 0;  // D3, m
  // The assembly torque's impedance (guidance/torque_law): the parameters
  // AssemblyTorque reads and the inertia it scales with, about the centre of
  // mass, part frame. The wrist law tau = Psi K theta - B omega is the
  // inertial law with unit inertia, w = sqrt(K) and zeta = B / (2 sqrt(K)).
  guidance::GuidanceParams torque_params;
  Eigen::Matrix3d torque_inertia_body = Eigen::Matrix3d::Zero();
  // guidance/compliance_centre "leading_end": in contact the operator's force
  // acts at the part's leading end (part frame) instead of the grasp.
  bool compliance_at_leading_end = false;
  Eigen::Vector3d leading_end = Eigen::Vector3d::Zero();
  // The contact normal force over which Eq. 7 passes into Eq. 8, N.
  double blend_force = 1.0;
  double clearance = 0;  // the smallest radial clearance to a fixed part, m (0: none)
  double penetration_bound = 0;   // m; 0: the scene has no radial fit to bound
  contact::BuiltContact contact;  // model null: nothing to touch, no contact work
  // Raycast, and something could hide the part: Eq. 1's casters against the
  // part's mesh and the fixed parts', tessellated once. The pool is the one
  // thing of the model that changes, under its own lock: each trial borrows a
  // caster for its duration (casting moves the part's instance in it), and
  // the pool builds one only when none is idle, so at most one per thread. A
  // copy of the model shares it: a caster depends on the meshes alone.
  std::shared_ptr<const visibility::CasterPool> casters;

  // The contact force element: the forces the part meets at m.
  contact::ContactForces ContactAt(const contact::RigidMotion& m,
                                   contact::ContactCounters* counters) const;
  // The operator force element: the force at the grasp point and the torque
  // about the body origin (world), with the contact `cf` the part meets at m.
  void OperatorLoad(const contact::RigidMotion& m, const Decision& d,
                    const contact::ContactForces& cf, Eigen::Vector3d* force,
                    Eigen::Vector3d* torque) const;
  // Both elements at m (gravity aside): the contact first, as the operator
  // feels it, then their sum, operator first (the order fixes the bits).
  // With `jacobian`, also their derivative, from the same contact pass (the
  // loads the same bits as without). With `phases`, the contact
  // evaluation's time is added to its contact and the operator's to its hand
  // (PhaseTimer).
  Loads LoadsAt(const contact::RigidMotion& m, const Decision& d,
                contact::ContactCounters* counters, LoadJacobian* jacobian = nullptr,
                PhaseSeconds* phases = nullptr) const;
  // The derivative of LoadsAt(m, d) given its `loads` and the contact's
  // derivative there (trial_model_jacobian.cc).
  LoadJacobian LoadJacobianAt(const contact::RigidMotion& m, const Decision& d,
                              const Loads& loads,
                              const contact::ContactJacobian& cj) const;

  // Distance and angle to the target, for completion and progress.
  double DistanceToTarget(const contact::RigidMotion& m) const;
  double AngleToTargetDeg(const contact::RigidMotion& m) const;
  // The completion witness, max(distance / d_th, angle / angle_th) - 1: it
  // falls through zero when the part comes within both thresholds (Sec. 3.1;
  // simulation/completion_distance and completion_angle_deg). Every stepper's
  // completion is its zero.
  double CompletionWitness(const contact::RigidMotion& m) const;
};

// The factor curves f, r and g (Figs. 3-5) of the scene's operator, as every
// trial of the scene evaluates them: r's breakpoints from the operator's arm
// length and stature. A lab track is measured with the same curves
// (calibrate/targets.h).
human::FactorCurves OperatorFactorCurves(const scene::Scene& scene);

// The model of the part at `sequence_position` of scene.sequence, against the
// base, parts with role "assembled" and the parts assembled before it (at
// their targets). InputError (naming scene.file) for what only building it
// can find: a visibility grid too fine, a tolerance the mesher refuses.
std::shared_ptr<const TrialModel> BuildTrialModel(const scene::Scene& scene,
                                                  int sequence_position);

// One model per entry of scene.sequence, in order.
std::vector<std::shared_ptr<const TrialModel>> BuildSequenceModels(
    const scene::Scene& scene);

}  // namespace vahf::sim
