#include "vahf/sim/internal/decisions.h"

#include <cmath>

#include "vahf/guidance/assembly_force.h"
#include "vahf/guidance/assembly_torque.h"
#include "vahf/human/fatigue.h"

namespace vahf::sim::internal {

namespace {

// The outcomes decided at decision i (outcome.h), from the factors f, Psi,
// and whether the part is in contact: may end the trial. And the rests
// (rest_watch.h), from the same distance and contact.
void CheckOutcomes(TrialContext& c, std::int64_t i, double time,
                   const contact::RigidMotion& m, const human::FactorValues& f,
                   double psi, bool in_contact) {
  const auto& p = c.params();
  DecisionFacts facts;
  facts.time = time;
  facts.operator_acts = c.model.operator_acts;
  facts.psi = psi;
  facts.work = c.work;
  facts.shoulder_distance = f.shoulder_distance;
  facts.reach_limit = c.model.reach_limit;
  facts.in_contact = in_contact;
  facts.distance = c.model.DistanceToTarget(m);
  c.progress.Observe(i == 0, facts.time, facts.distance, facts.in_contact,
                     p.simulation.jam_progress);
  // Before the rules that may end the trial: a jam's last interval rests too.
  c.Rested(c.rests.Observe(i, m.pose.translation(), facts.distance, facts.in_contact,
                           p.simulation));
  if (std::optional<Ending> end =
          CheckOperator(facts, p.fatigue, p.simulation, c.progress))
    c.End(std::move(*end));
}

// The operator's response to a stopped part (GuidanceParams::stall_time):
// a part that has rested in contact for stall_time is withdrawn towards the
// point withdraw_distance back from where it stopped, held at the target's
// orientation, until at a decision it is out of contact and within
// completion_angle_deg of that orientation (pulled free and realigned); then
// it is guided in again. Whether decision i withdraws, and where to.
bool Withdrawing(TrialContext& c, const contact::RigidMotion& m, bool in_contact) {
  const auto& p = c.params();
  if (!c.model.operator_acts || c.ended || !(p.guidance.stall_time > 0)) return false;
  if (c.withdrawal) {
    if (in_contact || c.model.AngleToTargetDeg(m) > p.simulation.completion_angle_deg)
      return true;
    c.withdrawal.reset();
  }
  // Whole intervals: 1e-9 of one below stall_time is at it.
  if (c.rests.OpenRest(p.simulation.decision_interval) <
      p.guidance.stall_time - 1e-9 * p.simulation.decision_interval)
    return false;
  c.withdrawal = guidance::WithdrawalTarget(m.pose.translation(), c.model.target.position,
                                            p.guidance.withdraw_distance);
  c.rests.Withdrew();
  c.progress.Withdrew();
  return true;
}

// What the operator holds from decision i: Eq. 5's estimated target and the
// held orientation, keyed by {seed, trial} and i; the part's own pose once
// the trial has ended. A part being withdrawn is pulled towards the
// withdrawal's point at the target's orientation instead, decision i's draws
// not used.
void Draw(TrialContext& c, std::int64_t i, const contact::RigidMotion& m,
          const Vector3d& centre, const human::FactorValues& f, bool in_contact,
          Decision* d) {
  const TrialModel& model = c.model;
  const auto& p = c.params();
  const Vector3d T = m.pose.translation();
  if (Withdrawing(c, m, in_contact)) {
    d->withdraw = true;
    d->estimated_target = *c.withdrawal;
    d->held_orientation = model.target.Rotation();
  } else if (!c.ended) {
    d->estimated_target = guidance::DrawEstimatedTarget(
        p.guidance, c.key, static_cast<std::uint64_t>(i), model.target.position, T,
        centre - model.posture.eye, f.eta, f.lambda_c, d->psi);
    d->held_orientation = guidance::DrawHeldOrientation(
        p.guidance, c.key, static_cast<std::uint64_t>(i), model.target.Rotation(), f.eta);
  } else {
    d->estimated_target = T;
    d->held_orientation = m.pose.linear();
  }
}

// The trace row of a decision at `time`.
void RecordDecision(TrialContext& c, double time, const contact::RigidMotion& m,
                    const Vector3d& force, const contact::ContactForces& cf,
                    const human::FactorValues& f, double psi) {
  TraceRow row = TrialContext::PoseRow(time, m);
  row.assembly_force = force;
  row.contact_force = cf.normal_force;
  row.friction_force = cf.friction_force;
  row.penetration = cf.max_depth;
  row.factors = f;
  row.work = c.work;
  row.psi = psi;
  c.trace.push_back(row);
}

std::optional<Decision> DecideNow(TrialContext& c, double time,
                                  const contact::RigidMotion& m) {
  const TrialModel& model = c.model;
  const auto& p = c.params();
  const std::int64_t i = std::llround(time / p.simulation.decision_interval);
  if (i <= c.last_decision) return std::nullopt;  // already decided at this instant
  c.last_decision = i;
  const Vector3d T = m.pose.translation();
  if (std::optional<Ending> bad =
          CheckState(m, model.bounding_radius, p.simulation, "decision", i, time)) {
    c.End(std::move(*bad));
    return std::nullopt;
  }

  // Fatigue: Eq. 4 over the last interval's travel with the force held then, Eq. 6.
  if (i > 0)
    c.work +=
        human::WorkEq4(c.last_force, human::TravelOf(T - c.last_position), p.fatigue.k);
  c.last_position = T;
  const double psi = human::FatigueCoefficient(c.work, p.fatigue.a_max);

  // Human factors at the part's centre of mass.
  const Vector3d centre = m.pose * model.part_com;
  const human::FactorValues f =
      c.FactorsAt(m, centre, c.MotionDirection(centre, T, i == 0));
  c.last_centre = centre;

  // Contact now: for the jam rule and the trace (the force law reads the
  // current contact at every evaluation, not this one).
  Decision d;
  d.psi = psi;
  d.practice_gain = c.practice_gain;
  const contact::ContactForces cf = c.ContactAt(m);
  const bool in_contact = cf.in_contact() && cf.normal_force.norm() > 0;
  if (in_contact && c.first_contact_time < 0) c.first_contact_time = time;
  CheckOutcomes(c, i, time, m, f, psi, in_contact);
  Draw(c, i, m, centre, f, in_contact, &d);

  Vector3d force, torque;
  model.OperatorLoad(m, d, cf, &force, &torque);
  c.last_force = force.norm();
  c.max_penetration = std::max(c.max_penetration, cf.max_depth);
  if (c.record_trace) RecordDecision(c, time, m, force, cf, f, psi);
  return d;
}

}  // namespace

std::optional<Decision> Decide(TrialContext& c, double time,
                               const contact::RigidMotion& m) {
  // V's ray casting and the decision's contact evaluation are their own
  // phases: what they took within is taken out.
  const double within = c.phases.visibility + c.phases.contact;
  std::optional<Decision> d;
  {
    const PhaseTimer timer(c.Timing(&PhaseSeconds::decisions));
    d = DecideNow(c, time, m);
  }
  c.phases.decisions -= c.phases.visibility + c.phases.contact - within;
  return d;
}

TraceRow FinalRow(TrialContext& c, double time, const contact::RigidMotion& m) {
  const TrialModel& model = c.model;
  const Vector3d T = m.pose.translation();
  const Vector3d centre = m.pose * model.part_com;
  TraceRow row = TrialContext::PoseRow(time, m);
  if (!IsFinite(m)) {  // a numerical failure's last state: A and Psi as last decided
    row.work = c.work;
    row.psi = human::FatigueCoefficient(c.work, c.params().fatigue.a_max);
    return row;
  }
  row.factors = c.FactorsAt(m, centre, c.MotionDirection(centre, T, false));
  row.work = c.work + human::WorkEq4(c.last_force, human::TravelOf(T - c.last_position),
                                     c.params().fatigue.k);
  row.psi = human::FatigueCoefficient(row.work, c.params().fatigue.a_max);
  if (model.contact.model) {
    const contact::ContactForces cf = c.ContactAt(m);
    row.contact_force = cf.normal_force;
    row.friction_force = cf.friction_force;
    row.penetration = cf.max_depth;
  }
  return row;
}

}  // namespace vahf::sim::internal
