// Does the contact resolve the fit? An independent geometric check
// (tests/support/penetration_oracle.h: the true surfaces from the profiles,
// none of the contact model's code) of trial trajectories sampled every
// 0.5 ms (TrialOptions::sample_interval): the assembling part against every
// fixed part must stay within 10 % of the scene's smallest radial clearance
// (docs/design.md decision 7). The oracle itself is first checked against closed
// forms: a cylinder offset sideways in a bore (depth e - c) and a tilted
// cylinder dipping its rim into a slab (depth R sin(theta) - h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/penetration_oracle.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial.h"

namespace vahf::sim {
namespace {

using testing::Penetration;
using testing::RevolvedSolid;

geometry::RevolvedProfile Profile(std::vector<geometry::ProfilePoint> p) {
  p.push_back(p.front());
  return geometry::MakeRevolvedProfile(p);
}

Eigen::Isometry3d At(const Eigen::Vector3d& x, double tilt_x_rad = 0) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = Eigen::AngleAxisd(tilt_x_rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
  p.translation() = x;
  return p;
}

TEST(PenetrationOracle, CylinderOffsetInABoreIsEMinusC) {
  const double R = 0.01, c = 50e-6;
  const RevolvedSolid peg(Profile({{0, 0}, {R, 0}, {R, 0.05}, {0, 0.05}}));
  const RevolvedSolid bore(Profile({{0, -0.05},
                                    {0.03, -0.05},
                                    {0.03, 0.0},
                                    {R + c, 0.0},
                                    {R + c, -0.04},
                                    {0, -0.04}}));
  const Eigen::Isometry3d bore_pose = At({0, 0, 0});
  for (double e : {20e-6, 60e-6, 150e-6}) {
    const double d = Penetration(peg, At({e, 0, -0.03}), bore, bore_pose);
    EXPECT_NEAR(d, std::max(0.0, e - c), 1e-9) << "offset " << e;
  }
}

TEST(PenetrationOracle, TiltedRimIntoASlabIsRSinThetaMinusH) {
  const double R = 0.01, h = 20e-6, theta = 0.5 * M_PI / 180;
  const RevolvedSolid peg(Profile({{0, 0}, {R, 0}, {R, 0.05}, {0, 0.05}}));
  const RevolvedSolid slab(Profile({{0, -0.1}, {0.2, -0.1}, {0.2, 0.0}, {0, 0.0}}));
  const double d = Penetration(peg, At({0, 0, h}, theta), slab, At({0, 0, 0}));
  EXPECT_NEAR(d, R * std::sin(theta) - h, 1e-9);
}

// The deepest the assembling part gets into any fixed part over a sampled
// trial, by the oracle.
double DeepestOverTrial(const scene::Scene& s, const TrialResult& r) {
  const scene::Part& moving = s.parts[static_cast<std::size_t>(s.sequence[0])];
  const RevolvedSolid m(std::get<geometry::RevolvedProfile>(moving.shape));
  double deepest = 0;
  for (const scene::Part& p : s.parts) {
    if (p.role != scene::Role::kBase) continue;
    const RevolvedSolid fixed(std::get<geometry::RevolvedProfile>(p.shape));
    for (const TraceRow& row : r.samples) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = row.orientation.toRotationMatrix();
      pose.translation() = row.position;
      deepest = std::max(deepest, Penetration(m, pose, fixed, p.initial.Transform()));
    }
  }
  return deepest;
}

// The shipped resolving configuration (experiments/scenes/peg_in_hole.json:
// stiffness by the bound rule with its barrier, the exact revolved contact,
// the co-contracted wrist, CVODE 3e-5 at BDF order at most 2).
TEST(FitResolution, PegStaysWithinTenPercentOfItsClearance) {
  const scene::Scene s = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                          "/experiments/scenes/peg_in_hole.json");
  ASSERT_EQ(s.params.contact.model, "resolving");
  TrialOptions options;
  options.record_trace = false;
  options.sample_interval = 0.5e-3;
  const TrialResult r = RunTrial(s, {1, 0}, options);
  ASSERT_EQ(r.status, Status::kCompleted) << r.detail;
  ASSERT_GT(r.samples.size(), 100u);
  const double deepest = DeepestOverTrial(s, r);
  std::printf(
      "peg seed 1: deepest %.3g um by the oracle, %.3g um by the contact model, "
      "bound %.3g um\n",
      deepest * 1e6, r.max_penetration * 1e6, r.penetration_bound * 1e6);
  EXPECT_NEAR(r.clearance, 50e-6, 1e-12);
  EXPECT_LT(deepest, 0.1 * r.clearance);
  EXPECT_EQ(r.warnings.at(WarningKind::kPenetrationBound).count, 0)
      << r.warnings.Summary();
  EXPECT_EQ(r.warnings.at(WarningKind::kNonFiniteState).count, 0) << r.warnings.Summary();
  EXPECT_EQ(r.warnings.at(WarningKind::kIntegratorFailure).count, 0)
      << r.warnings.Summary();
  EXPECT_LE(r.max_penetration, r.penetration_bound);
  // The stiffness rule (contact_params.h): F = kappa |T_0 - T_t| + m g over
  // 2 mm of edge sinks a quarter of the 5 um bound.
  const scene::Part& peg = s.parts[1];
  const double load =
      s.params.guidance.kappa * (peg.initial.position - peg.target.position).norm() +
      peg.mass * s.gravity.norm();
  EXPECT_NEAR(r.line_stiffness, load / (2e-3 * 0.25 * 5e-6), 1e-9 * r.line_stiffness);
  EXPECT_NEAR(r.stiffness, r.line_stiffness / 2e-3, 1e-9 * r.stiffness);
}

// The shipped resolved peg on seeds where it failed before, each for its own
// cause (docs/physics.md): 1000, a rim crossing a corner of the bore whose
// arc the scan missed (the peg ran 18 um through the barrier); 1012, the
// operator's Eq. 8 push growing with the friction of a wedged peg to 1e6 N
// (guidance/max_push 100 N: a person's push, docs/physics.md); 1029, a BDF
// order 3-5 mode growing without a contact force on the samples until the
// part passed 20 m/s (simulation/max_order); 46, the same growth at order 2
// from a Jacobian taken in contact and kept out of it (simulation/
// jacobian_interval 5; at CVODE's 51 it diverges); 209, a 0.64 ms step from
// free flight accepted 4.991 um deep, after which the corrector failed down
// to 1e-9 s steps (the stepper now takes back a step that deepens the
// contact by more than a quarter of the barrier); 313 and 1039, the 1.2 m/s
// strike on the bore's mouth, whose law ran 0.01 um past a barrier standing
// at the bound (the barrier now stands 2 % inside it, kBarrierMargin). Each
// must complete within the bound, by the model and by the geometric oracle.
TEST(FitResolution, ResolvedPegCompletesWithinTheBound) {
  const scene::Scene s = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                          "/experiments/scenes/peg_in_hole.json");
  TrialOptions options;
  options.record_trace = false;
  options.sample_interval = 0.5e-3;
  for (std::uint64_t seed : {1000u, 1012u, 1029u, 46u, 209u, 313u, 1039u}) {
    const TrialResult r = RunTrial(s, {seed, 0}, options);
    ASSERT_EQ(r.status, Status::kCompleted) << "seed " << seed << ": " << r.detail;
    const double deepest = DeepestOverTrial(s, r);
    std::printf(
        "peg seed %llu: deepest %.3g um by the oracle, %.3g um by the contact model\n",
        static_cast<unsigned long long>(seed), deepest * 1e6, r.max_penetration * 1e6);
    EXPECT_LT(deepest, r.penetration_bound) << "seed " << seed;
    EXPECT_LE(r.max_penetration, r.penetration_bound) << "seed " << seed;
    EXPECT_EQ(r.warnings.at(WarningKind::kPenetrationBound).count, 0)
        << "seed " << seed << ": " << r.warnings.Summary();
  }
}

// The resolved peg held by a co-contracted wrist (guidance/torque_law wrist,
// 20 N m/rad, 1 N m s/rad) on seeds 108 and 112: one CVODE step carried
// the peg's rim through the bore's chamfer between two clear ends, 9.3 and
// 13.7 um deep on its 0.5 ms samples against the 5 um bound, while every
// accepted step stayed within it. The stepper now checks the midpoint of a
// step that moves the part farther than the barrier's deepening limit and
// samples on the same Hermite path (docs/physics.md, Integrators). At CVODE
// 1e-4, the setting where the fault was found (the scene now takes 3e-5):
// without the midpoint check this test fails, 9.7 and 14.0 um by the oracle.
TEST(FitResolution, NoStepPassesThroughAContactNeitherEndTouches) {
  scene::Scene s = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                    "/experiments/scenes/peg_in_hole.json");
  s.params.simulation.accuracy = 1e-4;
  TrialOptions options;
  options.record_trace = false;
  options.sample_interval = 0.5e-3;
  for (std::uint64_t seed : {108u, 112u}) {
    const TrialResult r = RunTrial(s, {seed, 0}, options);
    ASSERT_EQ(r.status, Status::kCompleted) << "seed " << seed << ": " << r.detail;
    const double deepest = DeepestOverTrial(s, r);
    std::printf("wrist peg seed %llu: deepest %.3g um by the oracle\n",
                static_cast<unsigned long long>(seed), deepest * 1e6);
    EXPECT_LT(deepest, r.penetration_bound) << "seed " << seed;
  }
}

}  // namespace
}  // namespace vahf::sim
