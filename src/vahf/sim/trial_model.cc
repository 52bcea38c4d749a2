#include "vahf/sim/trial_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "vahf/core/error.h"
#include "vahf/geometry/clearance.h"
#include "vahf/guidance/assembly_force.h"
#include "vahf/guidance/assembly_torque.h"
#include "vahf/human/fatigue.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/phase_seconds.h"
#include "vahf/sim/stepper_registry.h"

namespace vahf::sim {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// A part that stands still during a trial, where it stands.
using scene::FixedPart;

// Eq. 1's casters, on the part's and the fixed parts' meshes at the scene's
// tolerance.
std::shared_ptr<const visibility::CasterPool> CastersFor(
    const scene::Scene& scene, const scene::Part& part,
    const std::vector<FixedPart>& fixed) {
  const auto& v = scene.params.visibility;
  if (v.grid > visibility::kMaxGrid)  // a scene built or changed in memory
    throw InputError(scene.file, "/parameters/visibility/grid", std::to_string(v.grid),
                     fmt::format("at most {} rays a side", visibility::kMaxGrid));
  // The mesher's errors know the value and rule but not the scene: add them.
  const auto mesh = [&](const scene::Part& p) {
    try {
      return geometry::Tessellate(p.shape, v.tessellation_tolerance);
    } catch (const InputError& e) {
      throw InputError(scene.file, "/parameters/visibility/tessellation_tolerance",
                       e.value(), fmt::format("{} (part '{}')", e.rule(), p.name));
    }
  };
  geometry::TriangleMesh part_mesh_P = mesh(part);  // the part first, as it fails first
  std::vector<visibility::Occluder> occluders;
  for (const FixedPart& f : fixed) occluders.push_back({mesh(*f.part), f.pose});
  visibility::CasterOptions options;
  options.grid = v.grid;
  return std::make_shared<const visibility::CasterPool>(std::move(part_mesh_P),
                                                        std::move(occluders), options);
}

// The end of the part along its own z axis that enters first: the one
// farther along the approach from its initial to its target position (part
// frame at the target orientation), on the axis.
Vector3d LeadingEnd(const scene::Part& part) {
  double lo = 0, hi = 0;
  if (const auto* p = std::get_if<geometry::RevolvedProfile>(&part.shape)) {
    lo = hi = p->vertices.front().z;
    for (const geometry::ProfilePoint& v : p->vertices) {
      lo = std::min(lo, v.z);
      hi = std::max(hi, v.z);
    }
  } else {
    const double half = 0.5 * std::get<geometry::Box>(part.shape).size.z();
    lo = -half;
    hi = half;
  }
  const Vector3d approach =
      part.target.Rotation().transpose() * (part.target.position - part.initial.position);
  return Vector3d(0, 0, approach.z() < 0 ? lo : hi);
}

// The moving mass: the part, and the operator's hand with it when the
// operator acts; their centre of mass and inertia.
void SetMass(const scene::Scene& scene, const scene::Part& part, TrialModel* m) {
  m->part_mass = part.mass;
  m->hand_mass = m->operator_acts ? scene.params.guidance.hand_mass : 0.0;
  m->mass = m->part_mass + m->hand_mass;
  m->part_com = part.mass_properties.centroid;
  m->bounding_radius = part.mass_properties.bounding_radius;
  // Parallel-axis sum of the part (principal axes = part axes) and the hand
  // point mass, about their common centre of mass.
  m->com = (m->part_mass * m->part_com + m->hand_mass * part.grasp) / m->mass;
  const auto shift = [](double mass, const Vector3d& d) {
    return (mass * (d.squaredNorm() * Matrix3d::Identity() - d * d.transpose())).eval();
  };
  m->inertia_body =
      Matrix3d((part.density * part.mass_properties.inertia_per_density).asDiagonal()) +
      shift(m->part_mass, m->part_com - m->com) +
      shift(m->hand_mass, part.grasp - m->com);
}

// The assembly torque's law (docs/design.md decision 3): the inertial servo
// as the scene sets it, or the wrist's stiffness and damping in its terms.
void SetTorqueLaw(const guidance::GuidanceParams& guidance, TrialModel* m) {
  m->torque_params = guidance;
  m->torque_inertia_body = m->inertia_body;
  if (guidance.torque_law == "wrist") {
    const double k = guidance.wrist_stiffness;
    m->torque_params.torque_frequency = std::sqrt(k);
    m->torque_params.torque_damping_ratio = guidance.wrist_damping / (2 * std::sqrt(k));
    m->torque_inertia_body = Matrix3d::Identity();
  }
}

// A stepper on contact points (MoreauJean) steps on the exact contact of
// solids of revolution (docs/design.md decision 16): a contact model that
// cannot give its points (a penalty on sampled points: contact/model "shell"
// or "sampled", or a pair that is not both revolved) is refused before any
// trial.
void RequireContactPoints(const scene::Scene& scene, const scene::Part& part,
                          const TrialModel& m) {
  if (FindStepper(scene.params.simulation.integrator).needs !=
          scene::StepperNeeds::kContactPoints ||
      !m.contact.model)
    return;
  contact::ContactCounters scratch;
  std::vector<contact::ContactPoint> points;
  contact::RigidMotion start;
  start.pose = part.initial.Transform();
  if (m.contact.model->AddContactPoints(start, 0.0, scratch, &points)) return;
  throw InputError(scene.file, "/parameters/simulation/integrator",
                   scene.params.simulation.integrator,
                   fmt::format("steps on the exact contact of solids of revolution: "
                               "contact/model \"resolving\" with part '{}' and every "
                               "fixed part it meets revolved (here contact/model is "
                               "\"{}\")",
                               part.name, scene.params.contact.model));
}

// The penetration bound and the contact model of the part against the fixed
// parts (none when nothing is fixed: no shell, no contact work).
void SetContact(const scene::Scene& scene, const scene::Part& part,
                const std::vector<FixedPart>& fixed, TrialModel* m) {
  const auto& params = scene.params;
  // The penetration bound: a fraction of the smallest radial clearance
  // between the part at its target and a fixed part (none: no bound).
  if (const auto tight = scene::TightestFit(part, fixed))
    m->clearance = tight->fit.clearance;
  m->penetration_bound = params.contact.penetration_fraction * m->clearance;
  if (fixed.empty()) return;
  contact::ContactSetup setup;
  setup.moving = {&part.shape, Eigen::Isometry3d::Identity(), part.friction,
                  part.mass_properties.bounding_radius};
  for (const FixedPart& f : fixed)
    setup.fixed.push_back({&f.part->shape, f.pose, f.part->friction,
                           f.part->mass_properties.bounding_radius});
  setup.params = params.contact;
  setup.penetration_bound = m->penetration_bound;
  setup.clearance = m->clearance;
  // The largest steady load: the operator's Eq. 7 pull at the start plus
  // the part's weight.
  const double pull =
      m->operator_acts
          ? params.guidance.kappa * (part.initial.position - part.target.position).norm()
          : 0.0;
  setup.steady_load = pull + part.mass * scene.gravity.norm();
  try {
    m->contact = contact::BuildContact(params.contact.model, setup);
  } catch (const InputError& e) {  // the contact knows the rule, not the scene
    throw InputError(scene.file, e.where(), e.value(),
                     fmt::format("{} (part '{}')", e.rule(), part.name));
  }
  RequireContactPoints(scene, part, *m);
}

// visibility/mode, one of the parameter table's three names.
TrialModel::Visibility VisibilityModeOf(const visibility::VisibilityParams& v) {
  if (v.mode == "raycast") return TrialModel::Visibility::kRaycast;
  if (v.mode == "constant") return TrialModel::Visibility::kConstant;
  VAHF_CHECK(v.mode == "off", "visibility mode '" + v.mode + "' is none of the table's");
  return TrialModel::Visibility::kOff;
}

}  // namespace

human::FactorCurves OperatorFactorCurves(const scene::Scene& scene) {
  const auto& params = scene.params;
  return {params.sight.Build(), params.reach.Build(scene.op.arm_length, scene.op.height),
          params.glance.Build()};
}

std::shared_ptr<const TrialModel> BuildTrialModel(const scene::Scene& scene,
                                                  int sequence_position) {
  const auto& params = scene.params;
  VAHF_CHECK(sequence_position >= 0 &&
                 sequence_position < static_cast<int>(scene.sequence.size()),
             "sequence position out of range");
  // The size rules, before anything is allocated: a scene changed after it
  // was read (an experiment's setting, a calibration's trial value) meets
  // them here if nowhere else.
  scene::RequireCountableSizes(scene);
  const scene::Part& part = scene.parts[scene.sequence[sequence_position]];
  auto out = std::make_shared<TrialModel>(OperatorFactorCurves(scene));
  TrialModel& m = *out;
  m.params = params;
  m.gravity = scene.gravity;
  m.part_name = part.name;
  m.initial = part.initial;
  m.target = part.target;
  m.grasp = part.grasp;
  m.visibility_mode = VisibilityModeOf(params.visibility);
  m.sequence_position = sequence_position;
  m.operator_acts = params.guidance.mode == "operator";
  SetMass(scene, part, &m);
  SetTorqueLaw(params.guidance, &m);
  m.compliance_at_leading_end = params.guidance.compliance_centre == "leading_end";
  m.leading_end = LeadingEnd(part);
  m.revolved = std::holds_alternative<geometry::RevolvedProfile>(part.shape);
  m.posture = human::StandingPosture(scene.op);
  m.reach_limit = params.reach.BreakpointsFor(scene.op.arm_length, scene.op.height).d3;
  // Eq. 7 passes into Eq. 8 over a fraction of the part's weight under
  // standard gravity (ISO 80000-3), whatever the scene's gravity.
  m.blend_force = params.guidance.contact_blend * part.mass * scene::kStandardGravity;

  const std::vector<FixedPart> fixed =
      scene::FixedPartsAt(scene, static_cast<std::size_t>(sequence_position));
  SetContact(scene, part, fixed, &m);
  // Eq. 1 by ray casting only when the scene asks for it and something could
  // hide the part; a scene with V given or switched off tessellates nothing.
  if (m.visibility_mode == TrialModel::Visibility::kRaycast && !fixed.empty())
    m.casters = CastersFor(scene, part, fixed);
  return out;
}

std::vector<std::shared_ptr<const TrialModel>> BuildSequenceModels(
    const scene::Scene& scene) {
  std::vector<std::shared_ptr<const TrialModel>> out;
  for (std::size_t p = 0; p < scene.sequence.size(); ++p)
    out.push_back(BuildTrialModel(scene, static_cast<int>(p)));
  return out;
}

contact::ContactForces TrialModel::ContactAt(const contact::RigidMotion& m,
                                             contact::ContactCounters* counters) const {
  return contact.model ? contact.model->Evaluate(m, counters) : contact::ContactForces{};
}

void TrialModel::OperatorLoad(const contact::RigidMotion& m, const Decision& d,
                              const contact::ContactForces& cf, Vector3d* force,
                              Vector3d* torque) const {
  *force = Vector3d::Zero();
  *torque = Vector3d::Zero();
  if (!operator_acts) return;
  const Matrix3d& R = m.pose.linear();
  const Vector3d r_grasp = R * grasp;
  // What the hand feels of the contact. Withdrawing a part it pulls against
  // the friction alone (guidance::WithdrawalForce), not along the contact,
  // as if out of it (the push at the grasp, the weight carried).
  const guidance::FeltContact felt{d.withdraw ? Vector3d::Zero() : cf.normal_force,
                                   cf.friction_force.norm()};
  // Where the push acts: the grasp; with the compliance centre at the
  // leading end, r_c = r_grasp + w R (leading end - grasp), passing to the
  // leading end as the contact blend w rises. It damps that point's velocity.
  Vector3d r_c = r_grasp;
  if (compliance_at_leading_end)
    r_c += guidance::ContactBlend(felt.normal_force.norm(), blend_force) *
           (R * (leading_end - grasp));
  const Vector3d v_c = m.velocity + m.angular_velocity.cross(r_c);
  const auto& g = params.guidance;
  // The arm always carries its own weight (at the grasp); the part's, as
  // guidance says.
  const Vector3d push =
      d.withdraw
          ? guidance::WithdrawalForce(
                g, d.Vigour(), mass, m.pose.translation(), d.estimated_target, v_c,
                felt.friction, part_mass * gravity, params.simulation.completion_distance)
          : guidance::ImpedanceForce(
                g, d.Vigour(), mass, m.pose.translation(), d.estimated_target, v_c, felt,
                blend_force, part_mass * gravity, params.simulation.completion_distance);
  *force = push - hand_mass * gravity;
  const Matrix3d inertia_world = R * torque_inertia_body * R.transpose();
  const Vector3d turn =
      guidance::AssemblyTorque(torque_params, d.Vigour(), inertia_world, R,
                               d.held_orientation, m.angular_velocity);
  if (compliance_at_leading_end)
    *torque = r_c.cross(push) - r_grasp.cross(hand_mass * gravity) + turn;
  else
    *torque = r_grasp.cross(*force) + turn;
}

Loads TrialModel::LoadsAt(const contact::RigidMotion& m, const Decision& d,
                          contact::ContactCounters* counters, LoadJacobian* jacobian,
                          PhaseSeconds* phases) const {
  Loads out;
  contact::ContactJacobian cj;
  {
    const PhaseTimer timer(phases ? &phases->contact : nullptr);
    out.contact = jacobian && contact.model ? contact.model->Evaluate(m, counters, &cj)
                                            : ContactAt(m, counters);
  }
  Vector3d torque;
  {
    const PhaseTimer timer(phases ? &phases->hand : nullptr);
    OperatorLoad(m, d, out.contact, &out.assembly_force, &torque);
  }
  out.force = out.assembly_force + out.contact.normal_force + out.contact.friction_force +
              out.contact.film_force;
  out.torque = torque + out.contact.torque;
  if (jacobian) *jacobian = LoadJacobianAt(m, d, out, cj);
  return out;
}

double TrialModel::DistanceToTarget(const contact::RigidMotion& m) const {
  return (m.pose.translation() - target.position).norm();
}

double TrialModel::AngleToTargetDeg(const contact::RigidMotion& m) const {
  const Matrix3d assembled = target.Rotation();
  if (revolved)  // a solid of revolution is assembled whatever its spin
    return human::AngleDeg(m.pose.linear().col(2), assembled.col(2));
  return Eigen::AngleAxisd(assembled.transpose() * m.pose.linear()).angle() * 180.0 /
         M_PI;
}

double TrialModel::CompletionWitness(const contact::RigidMotion& m) const {
  const scene::SimulationParams& sim = params.simulation;
  return std::max(DistanceToTarget(m) / sim.completion_distance,
                  AngleToTargetDeg(m) / sim.completion_angle_deg) -
         1.0;
}

}  // namespace vahf::sim
