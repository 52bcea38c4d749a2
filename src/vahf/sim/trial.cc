#include "vahf/sim/trial.h"

#include <Simbody.h>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "vahf/contact/contact_model.h"
#include "vahf/core/error.h"
#include "vahf/core/warnings.h"
#include "vahf/geometry/clearance.h"
#include "vahf/geometry/tessellation.h"
#include "vahf/guidance/assembly_force.h"
#include "vahf/guidance/assembly_torque.h"
#include "vahf/human/factors.h"
#include "vahf/human/fatigue.h"
#include "vahf/sim/integrators.h"
#include "vahf/sim/outcome.h"
#include "vahf/visibility/visibility.h"

namespace vahf::sim {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Travel between two decisions below which the part counts as still for f's
// direction of motion, m: well under a sensor's resolution.
constexpr double kStillDistance = 1e-6;

Vector3d ToEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }
SimTK::Vec3 ToSimTK(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Matrix3d ToEigen(const SimTK::Rotation& r) {
  Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[i][j];
  return m;
}
bool IsFinite(const contact::RigidMotion& m) {
  return m.pose.matrix().allFinite() && m.velocity.allFinite() &&
         m.angular_velocity.allFinite();
}
SimTK::Rotation ToSimTK(const Matrix3d& m) {
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

class OperatorAndContactForce : public SimTK::Force::Custom::Implementation {
 public:
  explicit OperatorAndContactForce(TrialContext* c) : c_(c) {}

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
    const contact::RigidMotion m = c_->MotionOf(s);
    ForceSnapshot& snap = SimTK::Value<ForceSnapshot>::updDowncast(
                              c_->forces->updCacheEntry(s, c_->snapshot_index))
                              .upd();
    snap = ForceSnapshot{};
    if (!IsFinite(m)) {  // no force from garbage; the step will be rejected or caught
      c_->warnings.Note(WarningKind::kNonFiniteState, s.getTime(),
                        "non-finite pose or velocity in a force evaluation");
      return;
    }
    if (c_->contact) snap.contact = c_->contact->Evaluate(m);
    Vector3d torque;
    c_->OperatorLoad(m, c_->HeldDecision(s), snap.contact, &snap.assembly_force, &torque);
    const Vector3d force =
        snap.assembly_force + snap.contact.normal_force + snap.contact.friction_force;
    torque += snap.contact.torque;
    body_forces[c_->body] += SimTK::SpatialVec(ToSimTK(torque), ToSimTK(force));
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

  void realizeTopology(SimTK::State& s) const override {
    c_->decision_index = c_->forces->allocateDiscreteVariable(
        s, SimTK::Stage::Dynamics, new SimTK::Value<Decision>(Decision{}));
    c_->snapshot_index = c_->forces->allocateCacheEntry(
        s, SimTK::Stage::Velocity, SimTK::Stage::Dynamics,
        new SimTK::Value<ForceSnapshot>(ForceSnapshot{}));
  }

 private:
  TrialContext* c_;
};

// The operator's decision at t_i = i * decision_interval: human factors,
// fatigue, the outcome checks, the Eq. 5 draws, the trace row.
void Decide(TrialContext& c, SimTK::State& s) {
  const auto& p = c.scene->params;
  const std::int64_t i = std::llround(s.getTime() / p.simulation.decision_interval);
  if (i <= c.last_decision) return;  // already decided at this instant
  c.last_decision = i;
  c.matter->getSystem().realize(s, SimTK::Stage::Velocity);
  const contact::RigidMotion m = c.MotionOf(s);
  const Vector3d T = m.pose.translation();
  if (std::optional<Ending> bad =
          CheckState(m, c.part->mass_properties.bounding_radius, p.simulation,
                     fmt::format("decision {}", i), s.getTime())) {
    c.End(std::move(*bad));
    return;
  }

  // Fatigue: Eq. 4 over the last interval's travel with the force held then, Eq. 6.
  if (i > 0)
    c.work +=
        human::WorkEq4(c.last_force, human::TravelOf(T - c.last_position), p.fatigue.k);
  c.last_position = T;
  const double psi = human::FatigueCoefficient(c.work, p.fatigue.a_max);

  // Human factors at the part's centre of mass.
  const Vector3d centre = m.pose * c.part_com;
  const human::FactorValues f = c.FactorsAt(m, centre, c.MotionDirection(centre, T, i == 0));
  c.last_centre = centre;

  // Contact now: for the jam rule and the trace (the force law reads the
  // current contact at every evaluation, not this one).
  Decision d;
  d.psi = psi;
  contact::ContactForces cf;
  if (c.contact) cf = c.contact->Evaluate(m);
  const bool in_contact = cf.in_contact() && cf.normal_force.norm() > 0;

  // Outcomes decided at this instant (outcome.h).
  DecisionFacts facts;
  facts.time = s.getTime();
  facts.operator_acts = c.operator_acts;
  facts.psi = psi;
  facts.work = c.work;
  facts.shoulder_distance = f.shoulder_distance;
  facts.reach_limit = c.reach_limit;
  facts.in_contact = in_contact;
  facts.distance = c.DistanceToTarget(m);
  c.progress.Observe(i == 0, facts.time, facts.distance, facts.in_contact,
                     p.simulation.jam_progress);
  if (std::optional<Ending> end = CheckOperator(facts, p.fatigue, p.simulation, c.progress))
    c.End(std::move(*end));

  // Eq. 5 and the held orientation, keyed by {seed, trial} and decision i.
  if (!c.ended) {
    d.estimated_target = guidance::DrawEstimatedTarget(
        p.guidance, c.key, static_cast<std::uint64_t>(i), c.part->target.position, T,
        centre - c.posture.eye, f.eta, f.lambda_c, psi);
    d.held_orientation =
        guidance::DrawHeldOrientation(p.guidance, c.key, static_cast<std::uint64_t>(i),
                                      c.part->target.Rotation(), f.eta);
  } else {
    d.estimated_target = T;
    d.held_orientation = m.pose.linear();
  }
  SimTK::Value<Decision>::updDowncast(c.forces->updDiscreteVariable(s, c.decision_index))
      .upd() = d;

  Vector3d force, torque;
  c.OperatorLoad(m, d, cf, &force, &torque);
  c.last_force = force.norm();
  c.max_penetration = std::max(c.max_penetration, cf.max_depth);
  if (c.record_trace) {
    TraceRow row = TrialContext::PoseRow(s.getTime(), m);
    row.assembly_force = force;
    row.contact_force = cf.normal_force;
    row.friction_force = cf.friction_force;
    row.penetration = cf.max_depth;
    row.factors = f;
    row.work = c.work;
    row.psi = psi;
    c.trace.push_back(row);
  }
}

// The row at the instant the trial ended: where the part is, its factors (f
// from the travel since the last decision), and A with that last stretch of
// travel added under the force held since the decision (Eq. 4).
TraceRow FinalRow(TrialContext& c, SimTK::State& s) {
  c.matter->getSystem().realize(s, SimTK::Stage::Velocity);
  const contact::RigidMotion m = c.MotionOf(s);
  const Vector3d T = m.pose.translation();
  const Vector3d centre = m.pose * c.part_com;
  TraceRow row = TrialContext::PoseRow(s.getTime(), m);
  row.factors = c.FactorsAt(m, centre, c.MotionDirection(centre, T, false));
  row.work = c.work + human::WorkEq4(c.last_force, human::TravelOf(T - c.last_position),
                                     c.scene->params.fatigue.k);
  row.psi = human::FatigueCoefficient(row.work, c.scene->params.fatigue.a_max);
  if (c.contact) {
    const contact::ContactForces cf = c.contact->Evaluate(m);
    row.contact_force = cf.normal_force;
    row.friction_force = cf.friction_force;
    row.penetration = cf.max_depth;
  }
  return row;
}

class DecisionHandler : public SimTK::PeriodicEventHandler {
 public:
  DecisionHandler(TrialContext* c, double interval)
      : SimTK::PeriodicEventHandler(interval), c_(c) {}
  void handleEvent(SimTK::State& s, SimTK::Real, bool& terminate) const override {
    Decide(*c_, s);
    terminate = c_->ended.has_value();
  }

 private:
  TrialContext* c_;
};

// Completion witness: max(|T - T_t| / d_th, angle / angle_th) - 1 falls through
// zero when both are below their thresholds; Simbody locates that instant.
class CompletionTrigger : public SimTK::TriggeredEventHandler {
 public:
  explicit CompletionTrigger(TrialContext* c)
      : SimTK::TriggeredEventHandler(SimTK::Stage::Position), c_(c) {
    getTriggerInfo().setTriggerOnRisingSignTransition(false);
  }
  SimTK::Real getValue(const SimTK::State& s) const override {
    const contact::RigidMotion m = c_->PoseOf(s);
    const auto& sim = c_->scene->params.simulation;
    return std::max(c_->DistanceToTarget(m) / sim.completion_distance,
                    c_->AngleToTargetDeg(m) / sim.completion_angle_deg) -
           1.0;
  }
  void handleEvent(SimTK::State& s, SimTK::Real, bool& terminate) const override {
    c_->ended = Status::kCompleted;
    c_->completion_time = s.getTime();
    c_->completion_row = FinalRow(*c_, s);  // Table 1's instant d, at this very state
    c_->detail = fmt::format("within {} m and {} deg of the target",
                             c_->scene->params.simulation.completion_distance,
                             c_->scene->params.simulation.completion_angle_deg);
    terminate = true;
  }

 private:
  TrialContext* c_;
};

// A part that stands still during this trial, where it stands.
struct FixedPart {
  const scene::Part* part;
  Eigen::Isometry3d pose;
};

// The base, parts with role "assembled", and the parts assembled earlier in
// the sequence (at their targets). Later parts are not in the trial at all.
std::vector<FixedPart> FixedParts(const scene::Scene& scene, int position) {
  std::vector<FixedPart> out;
  for (std::size_t k = 0; k < scene.parts.size(); ++k) {
    const scene::Part& p = scene.parts[k];
    const auto seq =
        std::find(scene.sequence.begin(), scene.sequence.end(), static_cast<int>(k));
    const bool assembled_earlier =
        seq != scene.sequence.end() && seq - scene.sequence.begin() < position;
    if (p.role == scene::Role::kAssembling && !assembled_earlier) continue;
    const scene::Pose& pose = p.role == scene::Role::kAssembling ? p.target : p.initial;
    out.push_back({&p, pose.Transform()});
  }
  return out;
}

// The checks made at every accepted step (docs/design.md decision 12): the
// state is finite, the contact depth is within the bound, the step is above
// the floor, and the integrator's retries since the last step are counted.
// Returns false when the state is unusable (the trial ends).
class StepWatch {
 public:
  explicit StepWatch(TrialContext& c) : c_(c) {}

  bool Accepted(const SimTK::Integrator& integ, const SimTK::State& s) {
    c_.matter->getSystem().realize(s, SimTK::Stage::Dynamics);
    const double t = s.getTime();
    const contact::RigidMotion m = c_.MotionOf(s);
    if (std::optional<Ending> bad = CheckState(
            m, c_.part->mass_properties.bounding_radius, c_.scene->params.simulation,
            fmt::format("a step after decision {}", c_.last_decision), t)) {
      if (!IsFinite(m)) c_.warnings.Note(WarningKind::kNonFiniteState, t, bad->detail);
      c_.End(std::move(*bad));
      return false;
    }
    Depth(c_.SnapshotOf(s).contact.max_depth, t);
    const double h = integ.getPreviousStepSizeTaken();
    const double floor = c_.scene->params.simulation.step_floor;
    if (h > 0 && h < floor)  // h = 0: no step since a restart
      c_.warnings.Note(WarningKind::kStepSizeFloor, t,
                       fmt::format("step {:.3g} s < floor {:.3g} s", h, floor));
    const std::int64_t retries = static_cast<std::int64_t>(integ.getNumConvergenceTestFailures()) +
                                 integ.getNumRealizationFailures() +
                                 integ.getNumProjectionFailures();
    if (retries > retries_)
      c_.warnings.Note(WarningKind::kIntegratorRetry, t,
                       fmt::format("{} convergence, {} realization, {} projection failures",
                                   integ.getNumConvergenceTestFailures(),
                                   integ.getNumRealizationFailures(),
                                   integ.getNumProjectionFailures()),
                       retries - retries_);
    retries_ = retries;
    return true;
  }

  // The deepest contact so far, and a warning past the bound.
  void Depth(double depth, double t) {
    c_.max_penetration = std::max(c_.max_penetration, depth);
    if (c_.penetration_bound > 0 && depth > c_.penetration_bound)
      c_.warnings.Note(WarningKind::kPenetrationBound, t,
                       fmt::format("depth {:.3g} um > bound {:.3g} um ({} of the {:.3g} um "
                                   "radial clearance)",
                                   depth * 1e6, c_.penetration_bound * 1e6,
                                   c_.scene->params.contact.penetration_fraction,
                                   c_.clearance * 1e6));
  }

 private:
  TrialContext& c_;
  std::int64_t retries_ = 0;
};

// A dense trace row at a sample state.
TraceRow SampleRow(TrialContext& c, const SimTK::State& s) {
  c.matter->getSystem().realize(s, SimTK::Stage::Dynamics);
  const ForceSnapshot& snap = c.SnapshotOf(s);
  TraceRow row = TrialContext::PoseRow(s.getTime(), c.MotionOf(s));
  row.assembly_force = snap.assembly_force;
  row.contact_force = snap.contact.normal_force;
  row.friction_force = snap.contact.friction_force;
  row.penetration = snap.contact.max_depth;
  row.work = c.work;
  row.psi = c.HeldDecision(s).psi;
  return row;
}

// Dense samples between accepted steps, by cubic Hermite interpolation of q
// (with qdot) and u (with udot) between the two step ends, the quaternion
// renormalised: third order, and the integrator never sees a sample time, so
// the trajectory is the same bits with and without samples whatever the
// integrator (asking the integrator for report times would not be: CPodes
// stops its steps at them).
class Sampler {
 public:
  Sampler(TrialContext& c, double interval) : c_(c), interval_(interval) {}

  // The integrator advanced to state `now` (realized to Acceleration): emit
  // every sample time in (previous, now], then remember `now`.
  void Advanced(const SimTK::State& now, double limit) {
    if (interval_ <= 0) return;
    if (have_previous_ && now.getTime() > t0_) {
      const double t1 = now.getTime(), h = t1 - t0_;
      for (;;) {
        const double t = static_cast<double>(next_) * interval_;
        if (t > t1 || t >= limit) break;
        const double s = (t - t0_) / h;
        // Hermite basis on [0, 1].
        const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
        const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
        SimTK::State x = now;
        x.setTime(t);
        x.updQ() = h00 * q0_ + (h10 * h) * qdot0_ + h01 * now.getQ() + (h11 * h) * now.getQDot();
        x.updU() = h00 * u0_ + (h10 * h) * udot0_ + h01 * now.getU() + (h11 * h) * now.getUDot();
        c_.matter->getSystem().realize(x, SimTK::Stage::Position);
        c_.matter->getSystem().project(x, 1e-10);  // the quaternion back to unit length
        c_.samples.push_back(SampleRow(c_, x));
        ++next_;
      }
    }
    have_previous_ = true;
    t0_ = now.getTime();
    q0_ = now.getQ();
    qdot0_ = now.getQDot();
    u0_ = now.getU();
    udot0_ = now.getUDot();
  }

 private:
  TrialContext& c_;
  double interval_;
  std::int64_t next_ = 1;
  bool have_previous_ = false;
  double t0_ = 0;
  SimTK::Vector q0_, qdot0_, u0_, udot0_;
};

// Steps from the initial state to completion, an ending or the time limit,
// returning at every accepted step (StepWatch, Sampler). Returns the time
// reached.
//
// The loop is SimTK::TimeStepper::stepTo's (Simbody 3.7, TimeStepper.cpp),
// returning at every internal step; time-advanced events are not dispatched
// (the system has none).
double Integrate(TrialContext& c, const SimTK::MultibodySystem& system,
                 SimTK::Integrator& integ, const SimTK::State& initial,
                 double sample_interval) {
  using SimTK::Integrator;
  const double limit = c.scene->params.simulation.time_limit;
  integ.setReturnEveryInternalStep(true);
  integ.initialize(initial);
  c.integrated = true;
  SimTK::HandleEventsOptions handle_options(integ.getConstraintToleranceInUse());
  if (integ.isInfinityNormInUse())
    handle_options.setOption(SimTK::HandleEventsOptions::UseInfinityNorm);
  StepWatch watch(c);
  Sampler sampler(c, sample_interval);
  sampler.Advanced(integ.getState(), limit);
  SimTK::Array_<SimTK::EventId> scheduled;
  double last_event_time = -SimTK::Infinity;
  const auto handle = [&](SimTK::Event::Cause cause, const SimTK::Array_<SimTK::EventId>& ids) {
    SimTK::HandleEventsResults results;
    system.handleEvents(integ.updAdvancedState(), cause, ids, handle_options, results);
    integ.reinitialize(results.getLowestModifiedStage(),
                       results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate);
  };
  while (!integ.isSimulationOver() && !c.ended) {
    const double now = integ.getTime();
    if (now >= limit) break;
    system.realize(integ.getState(), SimTK::Stage::Time);
    system.realize(integ.getAdvancedState(), SimTK::Stage::Time);
    double next_event = SimTK::Infinity;
    system.calcTimeOfNextScheduledEvent(integ.getState(), next_event, scheduled,
                                        last_event_time != now);
    const Integrator::SuccessfulStepStatus status =
        integ.stepTo(limit, std::min(next_event, limit));
    if (integ.getTime() > now) {  // the trajectory advanced to integ.getState()
      system.realize(integ.getState(), SimTK::Stage::Acceleration);
      if (!watch.Accepted(integ, integ.getState())) break;
      sampler.Advanced(integ.getState(), limit);
    }
    switch (status) {
      case Integrator::ReachedScheduledEvent:
        handle(SimTK::Event::Cause::Scheduled, scheduled);
        last_event_time = integ.getTime();
        break;
      case Integrator::ReachedEventTrigger:
        handle(SimTK::Event::Cause::Triggered, integ.getTriggeredEvents());
        break;
      case Integrator::EndOfSimulation:
        handle(SimTK::Event::Cause::Termination, {});
        break;
      default:  // TimeHasAdvanced, ReachedReportTime, StartOfContinuousInterval,
        continue;  // ReachedStepLimit: step on
    }
    // An event may have changed what the forces depend on (a decision):
    // interpolate the next step from the state after it.
    system.realize(integ.getState(), SimTK::Stage::Acceleration);
    sampler.Advanced(integ.getState(), limit);
  }
  return integ.getTime();
}

}  // namespace

TrialResult RunTrial(const scene::Scene& scene, rng::StreamKey key,
                     const TrialOptions& options) {
  const auto& params = scene.params;
  VAHF_CHECK(options.sequence_position >= 0 &&
                 options.sequence_position < static_cast<int>(scene.sequence.size()),
             "sequence position out of range");
  const scene::Part& part = scene.parts[scene.sequence[options.sequence_position]];

  TrialContext c({params.sight.Build(),
                  params.reach.Build(scene.op.arm_length, scene.op.height),
                  params.glance.Build()});
  c.scene = &scene;
  c.part = &part;
  c.key = key;
  c.operator_acts = params.guidance.mode == "operator";
  c.part_mass = part.mass;
  c.hand_mass = c.operator_acts ? params.guidance.hand_mass : 0.0;
  c.mass = c.part_mass + c.hand_mass;
  c.part_com = part.mass_properties.centroid;
  {
    // Parallel-axis sum of the part (principal axes = part axes) and the hand
    // point mass, about their common centre of mass.
    c.com = (c.part_mass * c.part_com + c.hand_mass * part.grasp) / c.mass;
    const auto shift = [](double m, const Vector3d& d) {
      return (m * (d.squaredNorm() * Matrix3d::Identity() - d * d.transpose())).eval();
    };
    c.inertia_body =
        Matrix3d((part.density * part.mass_properties.inertia_per_density).asDiagonal()) +
        shift(c.part_mass, c.part_com - c.com) + shift(c.hand_mass, part.grasp - c.com);
  }
  c.revolved = std::holds_alternative<geometry::RevolvedProfile>(part.shape);
  c.work = options.initial_work;
  c.record_trace = options.record_trace;
  c.posture = human::StandingPosture(scene.op);
  c.reach_limit = params.reach.BreakpointsFor(scene.op.arm_length, scene.op.height).d3;
  const std::vector<FixedPart> fixed = FixedParts(scene, options.sequence_position);
  // Eq. 7 passes into Eq. 8 over a fraction of the part's weight under
  // standard gravity (ISO 80000-3), whatever the scene's gravity.
  c.blend_force = params.guidance.contact_blend * part.mass * 9.80665;
  // The penetration bound: a fraction of the smallest radial clearance
  // between the part at its target and a fixed part (none: no bound).
  for (const FixedPart& f : fixed)
    if (const auto gap = geometry::SmallestRadialClearance(
            part.shape, part.target.Transform(), f.part->shape, f.pose))
      if (c.clearance == 0 || *gap < c.clearance) c.clearance = *gap;
  c.penetration_bound = params.contact.penetration_fraction * c.clearance;
  TrialCounters counters;
  if (!fixed.empty()) {  // nothing to touch: no shell, no contact work
    const bool resolving = params.contact.model == "resolving";
    const auto rims = [&](const geometry::Shape& shape) {
      return resolving ? contact::MakeRims(shape, params.contact.rim_spacing)
                       : std::vector<contact::RimPoint>{};
    };
    std::vector<contact::Obstacle> obstacles;
    for (const FixedPart& f : fixed)
      obstacles.push_back({contact::SignedDistance(f.part->shape), f.pose,
                           f.part->friction, f.part->mass_properties.bounding_radius,
                           rims(f.part->shape)});
    auto shell = contact::MakePointShell(part.shape, params.contact.shell_spacing);
    counters.shell_points = static_cast<std::int64_t>(shell.size());
    contact::ContactParams contact_params = params.contact;
    if (resolving && c.penetration_bound > 0) {
      contact_params.barrier_depth = c.penetration_bound;  // the bound it is checked against
      // docs/physics.md, Contact stiffness: the largest steady load sinks a
      // fraction of the bound over a short edge.
      const double pull = c.operator_acts ? params.guidance.kappa *
                                                (part.initial.position - part.target.position).norm()
                                          : 0.0;
      const double load = pull + part.mass * scene.gravity.norm();
      const double l = params.contact.rule_contact_length;
      contact_params.line_stiffness =
          load / (l * params.contact.rule_depth_fraction * c.penetration_bound);
      contact_params.stiffness = contact_params.line_stiffness / l;
    }
    c.stiffness = contact_params.stiffness;
    c.line_stiffness = resolving ? contact_params.line_stiffness : 0.0;  // no rims otherwise
    c.contact.emplace(std::move(shell), contact::SignedDistance(part.shape),
                      part.mass_properties.bounding_radius, part.friction,
                      std::move(obstacles), contact_params, rims(part.shape));
  }
  // Eq. 1 by ray casting only when the scene asks for it and something could
  // hide the part; a scene with V given or switched off tessellates nothing.
  if (params.visibility.mode == "raycast" && !fixed.empty()) {
    if (params.visibility.grid > visibility::kMaxGrid)
      throw InputError(scene.file, "/parameters/visibility/grid",
                       std::to_string(params.visibility.grid),
                       fmt::format("at most {} rays a side", visibility::kMaxGrid));
    const double tolerance = params.visibility.tessellation_tolerance;
    // The mesher's errors know the value and rule but not the scene: add them.
    const auto mesh = [&](const scene::Part& p) {
      try {
        return geometry::Tessellate(p.shape, tolerance);
      } catch (const InputError& e) {
        throw InputError(scene.file, "/parameters/visibility/tessellation_tolerance",
                         e.value(), fmt::format("{} (part '{}')", e.rule(), p.name));
      }
    };
    std::vector<visibility::Occluder> occluders;
    for (const FixedPart& f : fixed) occluders.push_back({mesh(*f.part), f.pose});
    visibility::CasterOptions caster_options;
    caster_options.grid = params.visibility.grid;
    c.caster.emplace(mesh(part), occluders, caster_options);
  }

  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter(system);
  SimTK::GeneralForceSubsystem forces(system);
  SimTK::Force::UniformGravity gravity(forces, matter, ToSimTK(scene.gravity));
  const Matrix3d& i = c.inertia_body;
  const SimTK::Inertia inertia_com(SimTK::Vec3(i(0, 0), i(1, 1), i(2, 2)),
                                   SimTK::Vec3(i(0, 1), i(0, 2), i(1, 2)));
  const SimTK::Body::Rigid body(
      SimTK::MassProperties(c.mass, ToSimTK(c.com),
                            inertia_com.shiftFromMassCenter(-ToSimTK(c.com), c.mass)));
  SimTK::MobilizedBody::Free mobod(matter.Ground(), SimTK::Transform(), body,
                                   SimTK::Transform());
  c.body = mobod.getMobilizedBodyIndex();
  c.matter = &matter;
  c.forces = &forces;
  SimTK::Force::Custom operator_force(forces, new OperatorAndContactForce(&c));
  system.addEventHandler(new DecisionHandler(&c, params.simulation.decision_interval));
  system.addEventHandler(new CompletionTrigger(&c));

  SimTK::State state = system.realizeTopology();
  mobod.setQToFitTransform(state, SimTK::Transform(ToSimTK(part.initial.Rotation()),
                                                   ToSimTK(part.initial.position)));
  Decide(c, state);

  const auto integ =
      MakeIntegrator(params.simulation.integrator, system, params.simulation.accuracy,
                     params.simulation.fixed_step);
  const auto start = std::chrono::steady_clock::now();
  TrialResult result;
  double end_time = 0;
  std::optional<TraceRow> final_row;
  if (c.ended) final_row = FinalRow(c, state);  // ended at the first decision
  if (!c.ended) {
    try {
      end_time = Integrate(c, system, *integ, state, options.sample_interval);
      if (c.completion_row) {
        final_row = c.completion_row;
      } else {
        SimTK::State end_state = integ->getState();
        final_row = FinalRow(c, end_state);
      }
      if (!c.ended && integ->isSimulationOver() &&
          integ->getTerminationReason() != SimTK::Integrator::ReachedFinalTime) {
        c.ended = Status::kNumericalFailure;
        c.detail = fmt::format(
            "integrator stopped at t = {} s: {}", end_time,
            SimTK::Integrator::getTerminationReasonString(integ->getTerminationReason()));
        c.warnings.Note(WarningKind::kIntegratorFailure, end_time, c.detail);
      }
    } catch (const std::exception& e) {
      end_time = integ->getTime();
      c.ended = Status::kNumericalFailure;
      c.detail = fmt::format("at t = {} s: {}", end_time, e.what());
      c.warnings.Note(WarningKind::kIntegratorFailure, end_time, c.detail);
    }
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.status = c.ended.value_or(Status::kTimeout);
  if (!c.ended) c.detail = fmt::format("time limit {} s", params.simulation.time_limit);
  result.detail = c.detail;
  result.end_time = result.status == Status::kCompleted ? c.completion_time : end_time;
  result.completion_time = c.completion_time;
  result.part = part.name;
  result.integrator = params.simulation.integrator;
  result.accuracy = params.simulation.accuracy;
  result.key = key;
  counters.decisions = c.last_decision + 1;
  counters.rays_cast = c.rays_cast;
  if (c.integrated) {  // an integrator never initialized has no counts to read
    counters.steps_taken = integ->getNumStepsTaken();
    counters.steps_attempted = integ->getNumStepsAttempted();
    counters.error_test_failures = integ->getNumErrorTestFailures();
    counters.realizations = integ->getNumRealizations();
  }
  if (c.contact) {
    counters.contact_evaluations =
        static_cast<std::int64_t>(c.contact->counters().evaluations);
    counters.contact_point_queries =
        static_cast<std::int64_t>(c.contact->counters().point_queries);
    counters.broad_phase_skips =
        static_cast<std::int64_t>(c.contact->counters().pairs_skipped);
    counters.clusters_skipped =
        static_cast<std::int64_t>(c.contact->counters().clusters_skipped);
  }
  result.counters = counters;
  result.warnings = c.warnings;
  result.max_penetration = c.max_penetration;
  result.penetration_bound = c.penetration_bound;
  result.clearance = c.clearance;
  result.stiffness = c.stiffness;
  result.line_stiffness = c.line_stiffness;
  result.samples = std::move(c.samples);
  if (!final_row) {  // the integrator threw: the last decision is the last known row
    final_row = c.trace.empty() ? TraceRow{} : c.trace.back();
    final_row->work = c.work;
  }
  result.final_row = *final_row;
  result.work = final_row->work;
  result.trace = std::move(c.trace);
  return result;
}

}  // namespace vahf::sim
