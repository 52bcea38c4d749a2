// What one trial holds while it runs, without Simbody: the shared, read-only
// model of its part (trial_model.h) and everything the trial mutates, so that
// trials run concurrently on the runner's threads without sharing state.
// The decisions (decisions.h), the Simbody model (simbody_trial.h) and the
// steppers (stepping.h, stepper_driver.h) work on it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "vahf/contact/contact_model.h"
#include "vahf/core/warnings.h"
#include "vahf/human/factors.h"
#include "vahf/rng/stream.h"
#include "vahf/sim/outcome.h"
#include "vahf/sim/phase_seconds.h"
#include "vahf/sim/rest_watch.h"
#include "vahf/sim/trial_model.h"
#include "vahf/sim/trial_result.h"
#include "vahf/visibility/caster_pool.h"

namespace vahf::sim::internal {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Travel between two decisions below which the part counts as still for f's
// direction of motion, m: well under a sensor's resolution.
constexpr double kStillDistance = 1e-6;

inline bool IsFinite(const contact::RigidMotion& m) {
  return m.pose.matrix().allFinite() && m.velocity.allFinite() &&
         m.angular_velocity.allFinite();
}

struct TrialContext {
  TrialContext(const TrialModel& trial_model, rng::StreamKey stream_key)
      : model(trial_model), key(stream_key) {
    if (model.casters) caster_lease.emplace(model.casters->Borrow());
  }

  const TrialModel& model;
  rng::StreamKey key;
  // Eq. 1 by ray casting: the model's caster this trial holds until it ends.
  std::optional<visibility::CasterPool::Lease> caster_lease;
  std::int64_t rays_cast = 0;
  contact::ContactCounters contact_counters;

  // Numerical health (docs/design.md decision 12).
  Warnings warnings;
  // The deepest contact at a decision, accepted step or sample, m.
  double max_penetration = 0;

  // Accumulators, updated at decision instants.
  std::int64_t last_decision = -1;
  double work = 0;
  double practice_gain = 1;  // G(n) of the trial's repetition (human/learning.h)
  Vector3d last_position = Vector3d::Zero();
  Vector3d last_centre = Vector3d::Zero();  // of the part, at the last decision
  double last_force = 0;
  ProgressWatch progress;
  RestWatch rests;  // observed at decisions (rest_watch.h)
  // Where the operator is withdrawing a stopped part to, while it does
  // (decisions.cc, GuidanceParams::stall_time).
  std::optional<Vector3d> withdrawal;
  std::optional<Status> ended;
  std::string detail;
  double completion_time = -1;
  // The first decision instant at which the part touched a fixed part (-1:
  // none yet).
  double first_contact_time = -1;
  std::optional<TraceRow> completion_row;
  std::vector<TraceRow> trace;
  std::vector<TraceRow> samples;  // every sample_interval of simulated time
  bool record_trace = true;
  // The integrator was initialized (its counters mean something).
  bool integrated = false;
  // CVODE: its own difference-quotient Jacobian instead of the analytic one
  // (TrialOptions, for comparisons).
  bool difference_quotient_jacobian = false;
  // A contact pass at every accepted step (TrialOptions, for comparisons).
  bool depth_pass_every_step = false;
  // Where the time goes, when asked (TrialOptions::time_phases).
  bool time_phases = false;
  PhaseSeconds phases;
  // The accumulator of one phase for a PhaseTimer: null when not timing.
  double* Timing(double PhaseSeconds::*phase) {
    return time_phases ? &(phases.*phase) : nullptr;
  }

  void End(Ending e) {
    ended = e.status;
    detail = std::move(e.detail);
  }

  // A rest RestWatch counted: one `rest` warning at its start.
  void Rested(const std::optional<Rest>& rest) {
    if (rest) warnings.Note(WarningKind::kRest, rest->start, rest->Detail());
  }

  const scene::Parameters& params() const { return model.params; }

  // A nonsmooth stepper's contact force (MoreauJean: its last step's net
  // impulse over the step), set by its core: what the decisions, samples and
  // final row report as the contact's normal force and friction, and what
  // the operator feels there, in place of the compliant law's at the state,
  // whose stiffness that stepper does not use. The depth stays the
  // geometry's, the oil film its own. Null: the compliant law's.
  const contact::ContactForces* nonsmooth_contact = nullptr;

  contact::ContactForces ContactAt(const contact::RigidMotion& m) {
    const PhaseTimer timer(Timing(&PhaseSeconds::contact));
    contact::ContactForces out = model.ContactAt(m, &contact_counters);
    Evaluated(m, out.max_depth);
    if (nonsmooth_contact) {
      out.normal_force = nonsmooth_contact->normal_force;
      out.friction_force = nonsmooth_contact->friction_force;
      out.points_in_contact = nonsmooth_contact->points_in_contact;
      out.rim_points_in_contact = nonsmooth_contact->rim_points_in_contact;
    }
    return out;
  }
  // TrialModel::LoadsAt with this trial's counters, its contact timed.
  Loads LoadsAt(const contact::RigidMotion& m, const Decision& d) {
    if (nonsmooth_contact) {
      Loads out;
      out.contact = ContactAt(m);
      Eigen::Vector3d torque;
      model.OperatorLoad(m, d, out.contact, &out.assembly_force, &torque);
      out.force = out.assembly_force + out.contact.normal_force +
                  out.contact.friction_force + out.contact.film_force;
      out.torque = torque;
      return out;
    }
    Loads out =
        model.LoadsAt(m, d, &contact_counters, nullptr, time_phases ? &phases : nullptr);
    Evaluated(m, out.contact.max_depth);
    return out;
  }

  // The last contact evaluated, whatever asked for it (a right-hand side, a
  // Jacobian, a check): the part's pose there and its deepest point, m; a
  // depth below zero: none yet. A bound on the depth nearby
  // (stepper_driver.cc, Drive::DepthAt).
  Eigen::Isometry3d evaluated_pose = Eigen::Isometry3d::Identity();
  double evaluated_depth = -1;
  void Evaluated(const contact::RigidMotion& m, double depth) {
    evaluated_pose = m.pose;
    evaluated_depth = depth;
  }

  // V (Eq. 1: cast, given, or 1) and the factors for the part at pose m with
  // its centre of mass at `centre`, moving along `motion` (non-zero).
  human::FactorValues FactorsAt(const contact::RigidMotion& m, const Vector3d& centre,
                                const Vector3d& motion) {
    double V = 1.0;  // "off", and "raycast" with nothing that could hide the part
    if (model.visibility_mode == TrialModel::Visibility::kConstant) {
      V = params().visibility.value;
    } else if (caster_lease) {
      const PhaseTimer timer(Timing(&PhaseSeconds::visibility));
      const visibility::VisibilityResult seen =
          caster_lease->caster().Compute(model.posture.eye, m.pose);
      V = seen.V;
      rays_cast += seen.rays_cast;
    }
    return human::EvaluateFactors(model.curves, model.posture, centre, motion, V);
  }

  // f's direction of motion as the paper measures it (Sec. 5.1): from the
  // part's centre at the previous decision to `centre`, P_i - P_{i-1}; with no
  // previous decision or no travel, the way from T to the target.
  Vector3d MotionDirection(const Vector3d& centre, const Vector3d& T, bool first) const {
    Vector3d motion = first ? Vector3d::Zero() : Vector3d(centre - last_centre);
    if (motion.norm() < kStillDistance) motion = model.target.position - T;
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

  // A dense sample row (any stepper's): the pose, the loads there, and A and
  // Psi as held since the last decision.
  TraceRow SampleRow(double time, const contact::RigidMotion& m, const Loads& loads,
                     double psi) const {
    TraceRow row = PoseRow(time, m);
    row.assembly_force = loads.assembly_force;
    row.contact_force = loads.contact.normal_force;
    row.friction_force = loads.contact.friction_force;
    row.penetration = loads.contact.max_depth;
    row.work = work;
    row.psi = psi;
    return row;
  }
};

}  // namespace vahf::sim::internal
