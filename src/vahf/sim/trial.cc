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
#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/stepping.h"
#include "vahf/sim/outcome.h"
#include "vahf/visibility/visibility.h"

namespace vahf::sim {
namespace {

using namespace internal;  // the trial context and the stepping loop
using Eigen::Matrix3d;
using Eigen::Vector3d;

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
                     "decision", i, s.getTime())) {
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
  c.blend_force = params.guidance.contact_blend * part.mass * scene::kStandardGravity;
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
