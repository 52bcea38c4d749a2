// What one trial holds while it runs, shared by the trial's Simbody model
// (trial.cc) and its stepping loop (stepping.cc); internal to src/vahf/sim.
// The trial context owns everything a trial mutates, so trials run
// concurrently on the runner's threads without sharing state.
#pragma once

#include <Simbody.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "vahf/contact/contact_model.h"
#include "vahf/core/warnings.h"
#include "vahf/guidance/assembly_force.h"
#include "vahf/guidance/assembly_torque.h"
#include "vahf/human/factors.h"
#include "vahf/human/fatigue.h"
#include "vahf/rng/stream.h"
#include "vahf/scene/scene.h"
#include "vahf/sim/outcome.h"
#include "vahf/sim/trial_result.h"
#include "vahf/visibility/visibility.h"

namespace vahf::sim::internal {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Travel between two decisions below which the part counts as still for f's
// direction of motion, m: well under a sensor's resolution.
constexpr double kStillDistance = 1e-6;

inline Vector3d ToEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }
inline SimTK::Vec3 ToSimTK(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline Matrix3d ToEigen(const SimTK::Rotation& r) {
  Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[i][j];
  return m;
}
inline bool IsFinite(const contact::RigidMotion& m) {
  return m.pose.matrix().allFinite() && m.velocity.allFinite() &&
         m.angular_velocity.allFinite();
}
inline SimTK::Rotation ToSimTK(const Matrix3d& m) {
  SimTK::Mat33 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m(i, j);
  return SimTK::Rotation(a, true);
}

// What the operator decided at the last decision instant, held until the next
// (docs/design.md decision 1). A Simbody discrete variable, so that changing it
// invalidates the state's dynamics and restarts the integrator cleanly.
// The contact it met is not held: the force law reads the current contact
// (guidance::ImpedanceForce), so the force is continuous in the state.
struct Decision {
  Vector3d estimated_target = Vector3d::Zero();  // T' of Eq. 5
  Matrix3d held_orientation = Matrix3d::Identity();
  double psi = 1.0;
};

// What the force element computed at a state, kept in a Simbody cache entry
// of that state so that an accepted step or a sample reads it without a
// second contact evaluation.
struct ForceSnapshot {
  Vector3d assembly_force = Vector3d::Zero();  // the operator's, at the grasp, N
  contact::ContactForces contact;
};

// Everything a trial needs at run time, owned for the trial's duration.
struct TrialContext {
  explicit TrialContext(human::FactorCurves factor_curves)
      : curves(std::move(factor_curves)) {}

  const scene::Scene* scene = nullptr;
  const scene::Part* part = nullptr;
  rng::StreamKey key;
  bool operator_acts = true;
  // The moving body: the part, plus the operator's hand and forearm as a point
  // mass at the grasp point (guidance/hand_mass) when an operator guides it.
  double part_mass = 0;
  double hand_mass = 0;
  double mass = 0;                           // part + hand
  Matrix3d inertia_body = Matrix3d::Zero();  // of both, about their centre of mass, part frame
  Vector3d com = Vector3d::Zero();           // of both, part frame
  Vector3d part_com = Vector3d::Zero();      // of the part alone: where factors look
  std::optional<contact::ContactModel> contact;
  std::optional<visibility::VisibilityCaster> caster;  // only for mode "raycast"
  std::int64_t rays_cast = 0;
  human::Posture posture;
  human::FactorCurves curves;
  double reach_limit = 0;  // D3, m
  bool revolved = false;   // orientation about the part's own z axis is free

  // Simbody handles.
  SimTK::MobilizedBodyIndex body;
  const SimTK::SimbodyMatterSubsystem* matter = nullptr;
  const SimTK::GeneralForceSubsystem* forces = nullptr;
  SimTK::DiscreteVariableIndex decision_index;
  SimTK::CacheEntryIndex snapshot_index;

  // The contact normal force over which Eq. 7 passes into Eq. 8, N.
  double blend_force = 1.0;
  // Numerical health (docs/design.md decision 12).
  Warnings warnings;
  double penetration_bound = 0;  // m; 0: the scene has no radial fit to bound
  double clearance = 0;          // the smallest radial clearance, m (0: none)
  double max_penetration = 0;    // deepest contact at an accepted step or sample, m
  double stiffness = 0, line_stiffness = 0;  // the contact's, as the trial set them

  // Accumulators, updated at decision instants.
  std::int64_t last_decision = -1;
  double work = 0;
  Vector3d last_position = Vector3d::Zero();
  Vector3d last_centre = Vector3d::Zero();  // of the part, at the last decision
  double last_force = 0;
  ProgressWatch progress;
  std::optional<Status> ended;
  std::string detail;
  double completion_time = -1;
  std::optional<TraceRow> completion_row;
  std::vector<TraceRow> trace;
  std::vector<TraceRow> samples;  // every sample_interval of simulated time
  bool record_trace = true;
  bool integrated = false;  // the integrator was initialized (its counters mean something)

  void End(Ending e) {
    ended = e.status;
    detail = std::move(e.detail);
  }

  const SimTK::MobilizedBody& Body() const { return matter->getMobilizedBody(body); }

  // The part's pose (needs Stage::Position), with zero velocities.
  contact::RigidMotion PoseOf(const SimTK::State& s) const {
    const SimTK::Transform& x = Body().getBodyTransform(s);
    contact::RigidMotion m;
    m.pose.linear() = ToEigen(x.R());
    m.pose.translation() = ToEigen(x.p());
    return m;
  }
  // Pose and velocities (needs Stage::Velocity).
  contact::RigidMotion MotionOf(const SimTK::State& s) const {
    contact::RigidMotion m = PoseOf(s);
    const SimTK::SpatialVec& v = Body().getBodyVelocity(s);
    m.angular_velocity = ToEigen(v[0]);
    m.velocity = ToEigen(v[1]);
    return m;
  }

  const Decision& HeldDecision(const SimTK::State& s) const {
    // The variable was allocated as a Value<Decision> in realizeTopology, so a
    // static cast is safe; Value::downcast's dynamic_cast cost 8 % of a trial.
    return static_cast<const SimTK::Value<Decision>&>(
               forces->getDiscreteVariable(s, decision_index))
        .get();
  }

  const ForceSnapshot& SnapshotOf(const SimTK::State& s) const {
    return static_cast<const SimTK::Value<ForceSnapshot>&>(
               forces->getCacheEntry(s, snapshot_index))
        .get();
  }

  // The operator's force at the grasp point and torque about the origin
  // (world), with the contact the part meets in this state.
  void OperatorLoad(const contact::RigidMotion& m, const Decision& d,
                    const contact::ContactForces& cf, Vector3d* force,
                    Vector3d* torque) const {
    *force = Vector3d::Zero();
    *torque = Vector3d::Zero();
    if (!operator_acts) return;
    const Vector3d r_grasp = m.pose.linear() * part->grasp;
    const Vector3d v_grasp = m.velocity + m.angular_velocity.cross(r_grasp);
    const auto& g = scene->params.guidance;
    // The arm always carries its own weight; the part's, as guidance says.
    const guidance::FeltContact felt{cf.normal_force, cf.friction_force.norm()};
    *force = guidance::ImpedanceForce(g, d.psi, mass, m.pose.translation(),
                                      d.estimated_target, v_grasp, felt, blend_force,
                                      part_mass * scene->gravity,
                                      scene->params.simulation.completion_distance) -
             hand_mass * scene->gravity;
    const Matrix3d inertia_world =
        m.pose.linear() * inertia_body * m.pose.linear().transpose();
    *torque = r_grasp.cross(*force) +
              guidance::AssemblyTorque(g, d.psi, inertia_world, m.pose.linear(),
                                       d.held_orientation, m.angular_velocity);
  }

  // V (Eq. 1: cast, given, or 1) and the factors for the part at pose m with
  // its centre of mass at `centre`, moving along `motion` (non-zero).
  human::FactorValues FactorsAt(const contact::RigidMotion& m, const Vector3d& centre,
                                const Vector3d& motion) {
    const auto& v = scene->params.visibility;
    double V = 1.0;  // "off", and "raycast" with nothing that could hide the part
    if (v.mode == "constant") {
      V = v.value;
    } else if (caster) {
      const visibility::VisibilityResult seen = caster->Compute(posture.eye, m.pose);
      V = seen.V;
      rays_cast += seen.rays_cast;
    }
    return human::EvaluateFactors(curves, posture, centre, motion, V);
  }

  // f's direction of motion as the paper measures it (Sec. 5.1): from the
  // part's centre at the previous decision to `centre`, P_i - P_{i-1}; with no
  // previous decision or no travel, the way from T to the target.
  Vector3d MotionDirection(const Vector3d& centre, const Vector3d& T, bool first) const {
    Vector3d motion = first ? Vector3d::Zero() : Vector3d(centre - last_centre);
    if (motion.norm() < kStillDistance) motion = part->target.position - T;
    if (motion.norm() < 1e-12) motion = -Vector3d::UnitZ();
    return motion;
  }

  // A trace row with the part's time, pose and velocities filled in.
  static TraceRow PoseRow(double time, const contact::RigidMotion& m) {
    TraceRow row;
    row.time = time;
    row.position = m.pose.translation();
    row.orientation = Eigen::Quaterniond(m.pose.linear());
    row.velocity = m.velocity;
    row.angular_velocity = m.angular_velocity;
    return row;
  }

  // Distance and angle to the target, for completion and progress.
  double DistanceToTarget(const contact::RigidMotion& m) const {
    return (m.pose.translation() - part->target.position).norm();
  }
  double AngleToTargetDeg(const contact::RigidMotion& m) const {
    const Matrix3d target = part->target.Rotation();
    if (revolved)  // a solid of revolution is assembled whatever its spin
      return human::AngleDeg(m.pose.linear().col(2), target.col(2));
    return Eigen::AngleAxisd(target.transpose() * m.pose.linear()).angle() * 180.0 / M_PI;
  }
};

}  // namespace vahf::sim::internal
