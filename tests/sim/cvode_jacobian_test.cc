// The loads' and the full 13 x 13 Jacobian CVODE is given
// (TrialModel::LoadsAt with a LoadJacobian, DerivativeJacobian) against
// central differences: the operator's force and torque with a flat box
// contact (exact: the operator reads the contact's normal force and friction)
// deep in contact and within the contact blend; the peg scenes at states in
// contact taken from a CVODE run, where the neglected curvature of the bore
// and the peg and the points that enter or leave contact within a step make
// the comparison inexact (the discrepancy is printed and bounded); and the
// analytic Jacobian against CVODE's difference quotients on a whole trial.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "support/motion_differences.h"
#include "vahf/guidance/assembly_torque.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/rigid_body_jacobian.h"
#include "vahf/sim/trial.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim {
namespace {

using Eigen::Vector3d;

const std::vector<int> kSegments = {3, 4, 3, 3};  // p, q, v, w

// A 20 x 20 x 10 mm aluminium block guided onto a steel floor whose top is
// z = 0.925 m.
scene::Scene BlockOnFloor() {
  const nlohmann::json doc = {
      {"format", "vahf-scene/1"},
      {"name", "block_on_floor"},
      {"operator",
       {{"height", 1.75},
        {"arm_length", 0.74},
        {"position", {0.0, -0.35}},
        {"facing_deg", 90}}},
      {"parts",
       {{{"name", "floor"},
         {"role", "base"},
         {"geometry", {{"type", "box"}, {"size", {0.3, 0.3, 0.05}}}},
         {"density", 7850},
         {"friction", 0.3},
         {"pose", {{"position", {0.0, 0.0, 0.9}}}}},
        {{"name", "block"},
         {"role", "assembling"},
         {"geometry", {{"type", "box"}, {"size", {0.02, 0.02, 0.01}}}},
         {"density", 2700},
         {"friction", 0.5},
         {"pose", {{"position", {0.0, 0.0, 0.94}}}},
         {"target", {{"position", {0.01, 0.0, 0.93}}}}}}},
      {"sequence", {"block"}},
      {"parameters", {{"visibility", {{"mode", "off"}}}}}};
  return scene::ParseScene(doc, "block_on_floor.json");
}

// The operator aims 5 mm into the floor, off to the side, and holds an
// orientation 0.2 rad from the block's.
Decision Aiming(const TrialModel& model) {
  Decision d;
  d.estimated_target = model.target.position + Vector3d(0.003, -0.002, -0.005);
  d.held_orientation =
      Eigen::AngleAxisd(0.2, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  d.psi = 0.9;
  return d;
}

// The block's bottom `depth` into the floor at its centre, tilted, sliding.
contact::RigidMotion Pressed(double depth, double tilt) {
  contact::RigidMotion m;
  m.pose.linear() =
      Eigen::AngleAxisd(tilt, Vector3d(1, 2, 0).normalized()).toRotationMatrix();
  m.pose.translation() = Vector3d(1.3e-3, -0.7e-3, 0.925 + 0.005 - depth);
  m.velocity = {0.05, 0.02, -0.01};
  m.angular_velocity = {0.2, -0.1, 0.3};
  return m;
}

Eigen::VectorXd Stacked(const Loads& l) {
  Eigen::VectorXd out(6);
  out << l.force, l.torque;
  return out;
}

// d(ydot)/dy by central differences, steps per state segment.
Eigen::MatrixXd StateDifferences(const TrialModel& model, const Decision& d,
                                 const BodyState& y, const std::array<double, 4>& h) {
  const auto f = [&](const BodyState& x) -> BodyState {
    return Derivative(model, x, model.LoadsAt(MotionOf(x), d, nullptr), model.gravity);
  };
  Eigen::MatrixXd out(kBodyStateSize, kBodyStateSize);
  for (int j = 0; j < kBodyStateSize; ++j) {
    const double e = h[j < 3 ? 0 : j < 7 ? 1 : j < 10 ? 2 : 3];
    BodyState up = y, down = y;
    up[j] += e;
    down[j] -= e;
    out.col(j) = (f(up) - f(down)) / (up[j] - down[j]);  // the step as represented
  }
  return out;
}

BodyJacobian Analytic(const TrialModel& model, const Decision& d, const BodyState& y) {
  LoadJacobian dl;
  const Loads loads = model.LoadsAt(MotionOf(y), d, nullptr, &dl);
  return DerivativeJacobian(model, y, loads, dl, model.gravity);
}

void ExpectJacobianWithAFlatContact(const scene::Scene& s, bool withdraw = false) {
  const auto model = BuildTrialModel(s, 0);
  Decision d = Aiming(*model);
  d.withdraw = withdraw;
  // 20 um deep (w = 1), and 50 nm deep and level: within the blend.
  struct Case {
    double depth, tilt;
    std::array<double, 4> steps;
  };
  for (const Case& c : {Case{20e-6, 1e-3, {1e-9, 1e-7, 1e-7, 1e-5}},
                        Case{50e-9, 1e-6, {1e-12, 1e-10, 1e-7, 1e-5}}}) {
    const contact::RigidMotion m = Pressed(c.depth, c.tilt);
    LoadJacobian analytic;
    const Loads loads = model->LoadsAt(m, d, nullptr, &analytic);
    ASSERT_GT(loads.contact.points_in_contact, 300);
    if (c.depth < 1e-6) {
      ASSERT_LT(loads.contact.normal_force.norm(), model->blend_force)
          << "not in the blend";
    }
    EXPECT_EQ(Stacked(loads), Stacked(model->LoadsAt(m, d, nullptr)));  // the same bits
    const Eigen::MatrixXd differences = vahf::testing::MotionDifferences(
        [&](const contact::RigidMotion& x) {
          return Stacked(model->LoadsAt(x, d, nullptr));
        },
        m, c.steps);
    EXPECT_TRUE(vahf::testing::BlocksAgree(analytic, differences, 1e-5)) << c.depth;
    // And the state's Jacobian, through the quaternion.
    const BodyState y = StateOf(m);
    EXPECT_TRUE(vahf::testing::BlocksAgree(
        Analytic(*model, d, y),
        StateDifferences(*model, d, y,
                         {c.steps[0], c.steps[1] / 2, c.steps[2], c.steps[3]}),
        1e-5, 1e-8, kSegments, kSegments))
        << c.depth;
  }
}

TEST(CvodeJacobian, OperatorWithAFlatContact) {
  ExpectJacobianWithAFlatContact(BlockOnFloor());
}

// The wrist's torque law, and the push passing to the block's leading end
// (its bottom face's centre) as the contact blend rises: the blend's own
// derivative enters the torque.
TEST(CvodeJacobian, WristAndComplianceAtTheLeadingEnd) {
  scene::Scene s = BlockOnFloor();
  s.params.guidance.torque_law = "wrist";
  s.params.guidance.compliance_centre = "leading_end";
  s.parts[1].grasp = Vector3d(0.004, -0.003, 0.005);  // off the leading end
  const auto model = BuildTrialModel(s, 0);
  ASSERT_EQ(model->leading_end, Vector3d(0, 0, -0.005));
  ExpectJacobianWithAFlatContact(s);
}

// A part the operator withdraws (guidance/stall_time): the hand pulls
// against the contact's friction alone (guidance::WithdrawalForce), so its
// force and torque do not change with the contact's normal force and grow
// with the friction; and the loads' Jacobian, without the derivative through
// the normal, still agrees with differences.
TEST(CvodeJacobian, AWithdrawingHandReadsTheFrictionAlone) {
  scene::Scene s = BlockOnFloor();
  s.params.guidance.torque_law = "wrist";
  s.params.guidance.compliance_centre = "leading_end";
  s.parts[1].grasp = Vector3d(0.004, -0.003, 0.005);
  const auto model = BuildTrialModel(s, 0);
  Decision d = Aiming(*model);
  d.withdraw = true;
  const contact::RigidMotion m = Pressed(20e-6, 1e-3);
  const contact::ContactForces cf = model->ContactAt(m, nullptr);
  ASSERT_GT(cf.normal_force.norm(), model->blend_force);
  ASSERT_GT(cf.friction_force.norm(), 0);
  Vector3d force, torque;
  model->OperatorLoad(m, d, cf, &force, &torque);
  contact::ContactForces other_normal = cf;
  other_normal.normal_force = 3.0 * cf.normal_force + Vector3d(1, -2, 0);
  Vector3d f2, t2;
  model->OperatorLoad(m, d, other_normal, &f2, &t2);
  EXPECT_EQ(force, f2);
  EXPECT_EQ(torque, t2);
  contact::ContactForces no_friction = cf;
  no_friction.friction_force.setZero();
  model->OperatorLoad(m, d, no_friction, &f2, &t2);
  // The friction's size, added along the pull d = T_w - T, faded over e as
  // Eq. 8's push is (max_push 0: unbounded).
  const double reach = (d.estimated_target - m.pose.translation()).norm();
  const double e = s.params.simulation.completion_distance;
  EXPECT_NEAR((force - f2).norm(),
              cf.friction_force.norm() * reach / std::sqrt(reach * reach + e * e),
              1e-9 * cf.friction_force.norm());
  EXPECT_GT((force - f2).dot(d.estimated_target - m.pose.translation()), 0);
  ExpectJacobianWithAFlatContact(s, true);
}

// The laws' stiffness and damping are the values they are given: the wrist's
// tau = Psi K theta - B omega whatever the part, the inertial law's
// I (Psi w^2 theta - 2 zeta w omega), the force's -kappa Psi and
// -2 zeta sqrt(kappa Psi m) per metre and metre per second; and with the
// compliance centre at the leading end, a part deep in contact is pushed at
// its leading end.
TEST(CvodeJacobian, HandLawsHaveTheStiffnessAndDampingTheyAreGiven) {
  scene::Scene s = BlockOnFloor();
  s.params.guidance.torque_law = "wrist";
  s.params.guidance.wrist_stiffness = 3.0;
  s.params.guidance.wrist_damping = 0.2;
  const Vector3d axis = Vector3d(1, -2, 0.5).normalized();
  Decision d;
  d.psi = 0.8;
  d.held_orientation = Eigen::AngleAxisd(0.01, axis).toRotationMatrix();
  contact::RigidMotion m;  // high above the floor: no contact
  m.pose.translation() = Vector3d(0, 0, 1.2);
  m.angular_velocity = Vector3d(0.3, -0.2, 0.1);
  const auto torque_of = [&](const scene::Scene& scene) {
    const auto model = BuildTrialModel(scene, 0);
    Vector3d force, torque;
    model->OperatorLoad(m, d, {}, &force, &torque);
    return torque;  // the grasp is the origin: no moment of the force
  };
  const Vector3d wrist = 0.8 * 3.0 * 0.01 * axis - 0.2 * m.angular_velocity;
  EXPECT_LT((torque_of(s) - wrist).norm(), 1e-12 * wrist.norm());
  // The same part under the inertial law: its inertia times w^2 and 2 zeta w.
  s.params.guidance.torque_law = "inertial";
  s.params.guidance.torque_frequency = 30;
  s.params.guidance.torque_damping_ratio = 0.7;
  const Eigen::Matrix3d inertia = BuildTrialModel(s, 0)->inertia_body;
  const Vector3d inertial =
      inertia * (0.8 * 900 * 0.01 * axis - 2 * 0.7 * 30 * m.angular_velocity);
  EXPECT_LT((torque_of(s) - inertial).norm(), 1e-12 * inertial.norm());
  // The force: stiffness kappa Psi and damping 2 zeta sqrt(kappa Psi m), in
  // free motion (linear in position and velocity).
  const auto model = BuildTrialModel(s, 0);
  const auto force_at = [&](const contact::RigidMotion& x) {
    Vector3d force, torque;
    model->OperatorLoad(x, d, {}, &force, &torque);
    return force;
  };
  contact::RigidMotion moved = m, faster = m;
  moved.pose.translation().x() += 1e-3;
  faster.velocity.x() += 1e-3;
  const double kappa_psi = s.params.guidance.kappa * 0.8;
  const double damping =
      2 * s.params.guidance.damping_ratio * std::sqrt(kappa_psi * model->mass);
  EXPECT_NEAR((force_at(moved) - force_at(m)).x() / 1e-3, -kappa_psi, 1e-9 * kappa_psi);
  EXPECT_NEAR((force_at(faster) - force_at(m)).x() / 1e-3, -damping, 1e-9 * damping);
}

TEST(CvodeJacobian, ComplianceAtTheLeadingEndPushesThereInContact) {
  scene::Scene s = BlockOnFloor();
  s.params.guidance.compliance_centre = "leading_end";
  s.parts[1].grasp = Vector3d(0.004, -0.003, 0.005);
  const auto model = BuildTrialModel(s, 0);
  const Decision d = Aiming(*model);
  const contact::RigidMotion m = Pressed(20e-6, 1e-3);  // the blend is 1
  const contact::ContactForces cf = model->ContactAt(m, nullptr);
  ASSERT_GT(cf.normal_force.norm(), model->blend_force);
  Vector3d force, torque;
  model->OperatorLoad(m, d, cf, &force, &torque);
  const Eigen::Matrix3d R = m.pose.linear();
  const Vector3d turn = guidance::AssemblyTorque(
      model->torque_params, d.psi, R * model->torque_inertia_body * R.transpose(), R,
      d.held_orientation, m.angular_velocity);
  const Vector3d expected = (R * model->leading_end).cross(force) + turn;  // no hand mass
  EXPECT_LT((torque - expected).norm(), 1e-12 * torque.norm());
  // At the grasp, it would have turned the block the other way about.
  s.params.guidance.compliance_centre = "grasp";
  Vector3d at_grasp_force, at_grasp;
  BuildTrialModel(s, 0)->OperatorLoad(m, d, cf, &at_grasp_force, &at_grasp);
  EXPECT_GT((at_grasp - torque).norm(), 1e-3 * torque.norm());
}

TEST(CvodeJacobian, OperatorInFreeMotion) {
  scene::Scene s = BlockOnFloor();
  const auto model = BuildTrialModel(s, 0);
  contact::RigidMotion m = Pressed(-1e-3, 0.05);  // 1 mm above the floor
  LoadJacobian analytic;
  const Loads loads = model->LoadsAt(m, Aiming(*model), nullptr, &analytic);
  ASSERT_FALSE(loads.contact.in_contact());
  const Eigen::MatrixXd differences = vahf::testing::MotionDifferences(
      [&](const contact::RigidMotion& x) {
        return Stacked(model->LoadsAt(x, Aiming(*model), nullptr));
      },
      m, {1e-7, 1e-7, 1e-7, 1e-7});
  EXPECT_TRUE(vahf::testing::BlocksAgree(analytic, differences, 1e-6));
}

// States in contact from the trial itself, seed 1, CVODE 1e-4.
std::vector<TraceRow> ContactStates(const scene::Scene& s) {
  const TrialResult r = RunTrial(s, {1, 0}, {0, 0.0, true, 0.5e-3});
  std::vector<TraceRow> in_contact;
  for (const TraceRow& row : r.samples)
    if (row.penetration > 0) in_contact.push_back(row);
  std::vector<TraceRow> out;
  for (std::size_t k = 0; k < 4 && !in_contact.empty(); ++k)
    out.push_back(in_contact[k * (in_contact.size() - 1) / 3]);
  return out;
}

// A comparison's message without the matrices.
std::string Head(const std::string& message) {
  return message.substr(0, message.find("\nanalytic"));
}

// Every block within `tolerance`, and within `shallow` where the contact is
// under `shallow_depth`: the neglected curvature term grows with the depth (it
// is about depth / radius of the force's turning) and with the points near a
// medial axis of the fields, whose normal jumps within a difference step.
// `model`: the scene's contact model, or another.
void ComparePegStates(const std::string& file, const std::string& model_name,
                      double tolerance, double shallow, double shallow_depth = 10e-6) {
  scene::Scene s =
      scene::LoadScene(std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/" + file);
  s.params.simulation.integrator = "CVODE";
  s.params.simulation.accuracy = 1e-4;
  if (!model_name.empty()) s.params.contact.model = model_name;
  const auto model = BuildTrialModel(s, 0);
  const std::vector<TraceRow> states = ContactStates(s);
  ASSERT_EQ(states.size(), 4u);
  for (const TraceRow& row : states) {
    contact::RigidMotion m;
    m.pose.linear() = row.orientation.normalized().toRotationMatrix();
    m.pose.translation() = row.position;
    m.velocity = row.velocity;
    m.angular_velocity = row.angular_velocity;
    Decision d = Aiming(*model);
    d.held_orientation = model->target.Rotation();
    d.psi = row.psi;
    const BodyState y = StateOf(m);
    const Eigen::MatrixXd analytic = Analytic(*model, d, y);
    const Eigen::MatrixXd differences =
        StateDifferences(*model, d, y, {1e-10, 1e-9, 1e-7, 1e-6});
    const auto exact = vahf::testing::BlocksAgree(analytic, differences, 1e-5, 1e-8,
                                                  kSegments, kSegments);
    const auto close = vahf::testing::BlocksAgree(analytic, differences, tolerance, 1e-6,
                                                  kSegments, kSegments);
    std::printf("%s (%s) t = %.4f s, depth %.3g um: exact %s; at %g: %s\n", file.c_str(),
                s.params.contact.model.c_str(), row.time, row.penetration * 1e6,
                exact ? "yes" : "no", tolerance, Head(close.message()).c_str());
    EXPECT_TRUE(close) << file << " t = " << row.time;
    if (row.penetration < shallow_depth) {
      EXPECT_TRUE(vahf::testing::BlocksAgree(analytic, differences, shallow, 1e-6,
                                             kSegments, kSegments))
          << file << " t = " << row.time;
    }
  }
}

// Measured: the worst block off by 8.8 % at 244 um (the shell contact's
// strike on the chamfer), 3.9 % at 144 um, 2.3 % at 32 um, 0.1 % at 4.9 um.
TEST(CvodeJacobian, PegStatesFromATrial) {
  ComparePegStates("peg_in_hole_shell.json", "", 0.12, 5e-3);
}

// The resolved peg on the sampled contact: measured 0.2 % at 2.2 um, 0.002 %
// at 0.15 um.
TEST(CvodeJacobian, SampledPegStatesFromATrial) {
  ComparePegStates("peg_in_hole.json", "sampled", 0.01, 5e-3);
}

// The resolved peg on its exact contact (the scene's): the Jacobian holds
// each quadrature node where it is, leaving out how the nodes move with the
// arc's ends and deepest point (revolved_contact.h). That is small while the
// load is under the steady load (RevolvedContact.
// AnalyticJacobianAgreesWithCentralDifferences), but where the barrier
// peaks the arc's load and the 4-point rule is coarse it is not. Measured
// on seed 1's states: 0.03 % of a block at 0.08-0.16 um deep, and 16 % at
// 2.94 um (t = 0.0325 s, several steady loads; the difference quotients the
// same for steps of 1e-11 to 1e-7 m, so the error is the Jacobian's). CVODE
// needs only a Jacobian good enough for its Newton iteration to converge.
TEST(CvodeJacobian, ResolvedPegStatesFromATrial) {
  ComparePegStates("peg_in_hole.json", "", 0.2, 5e-3, 1e-6);
}

// A whole trial: the analytic Jacobian and CVODE's difference quotients give
// the same completion time within the tolerance's effect, the analytic one
// without the 13 right-hand sides per Jacobian.
TEST(CvodeJacobian, AgreesWithDifferenceQuotientsOnATrial) {
  scene::Scene s = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                    "/experiments/scenes/peg_in_hole_shell.json");
  s.params.simulation.integrator = "CVODE";
  s.params.simulation.accuracy = 1e-8;
  TrialOptions dq;
  dq.difference_quotient_jacobian = true;
  const TrialResult analytic = RunTrial(s, {1, 0});
  const TrialResult reference = RunTrial(s, {1, 0}, dq);
  ASSERT_EQ(analytic.status, Status::kCompleted) << analytic.detail;
  ASSERT_EQ(reference.status, Status::kCompleted) << reference.detail;
  // As CVODE agrees with RungeKuttaMerson at 1e-8 (cvode_stepper_test.cc).
  EXPECT_NEAR(analytic.completion_time, reference.completion_time,
              1e-4 * reference.completion_time);
  EXPECT_GT(analytic.counters.jacobian_evaluations, 0);
  EXPECT_LT(
      analytic.counters.realizations,
      reference.counters.realizations - 13 * reference.counters.jacobian_evaluations / 2);
}

}  // namespace
}  // namespace vahf::sim
