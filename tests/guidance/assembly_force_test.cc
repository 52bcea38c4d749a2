// Eq. 5 (estimated target), E_i, Eq. 7 and Eq. 8. Deterministic cases by hand;
// the statistical ones (N = 100000 draws, bounds of 5 standard errors) check
// the mean of T' and the anisotropy of E_i. The operator's force between
// decisions against its two limits (Eq. 7 out of contact, Eq. 8 in full
// contact) and for continuity in the contact it feels: as the normal force
// tends to 0 from any direction the force tends to the free one, and a sweep
// of the normal force through the blend has no jump.
#include "vahf/guidance/assembly_force.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vahf::guidance {
namespace {

const Eigen::Vector3d kTarget(0.0, 0.0, 0.9);
const Eigen::Vector3d kPosition(0.1, -0.2, 1.1);

TEST(EstimatedTarget, Eq5ByHand) {
  const Eigen::Vector3d none = Eigen::Vector3d::Zero();
  // c = 0: the operator aims at the target itself.
  EXPECT_EQ(EstimatedTarget(kTarget, kPosition, 0.3, 0.9, Eigen::Vector3d::Zero(), none),
            kTarget);
  // c = 1 and lambda_c = Psi_c: T' is the current position.
  EXPECT_NEAR(
      (EstimatedTarget(kTarget, kPosition, 0.5, 0.5, Eigen::Vector3d::Ones(), none) -
       kPosition)
          .norm(),
      0.0, 1e-15);
  // Componentwise c, and E_i adds.
  const Eigen::Vector3d t =
      EstimatedTarget(kTarget, kPosition, 0.2, 0.8, Eigen::Vector3d(1.0, 0.5, 0.0),
                      Eigen::Vector3d(0.01, 0, 0));
  EXPECT_NEAR(t.x(), 0.25 * 0.1 + 0.01, 1e-15);
  EXPECT_NEAR(t.y(), 0.25 * 0.5 * -0.2, 1e-15);
  EXPECT_NEAR(t.z(), 0.9, 1e-15);
}

TEST(EstimatedTargetDeathTest, PsiZeroIsABug) {
  EXPECT_DEATH(EstimatedTarget(kTarget, kPosition, 0.3, 0.0, Eigen::Vector3d::Zero(),
                               Eigen::Vector3d::Zero()),
               "divides by Psi_c");
}

TEST(DrawEstimatedTarget, MeanIsHalfwayScaledByLambdaOverPsi) {
  // E[c] = 1/2 and E[E_i] = 0: E[T'] = T_t + lambda_c / Psi_c / 2 (T - T_t).
  const GuidanceParams params;
  const double lambda = 0.6, psi = 0.8;
  const int n = 100000;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i)
    mean += DrawEstimatedTarget(params, {17, static_cast<std::uint64_t>(i)}, 0, kTarget,
                                kPosition, Eigen::Vector3d(0, 1, -1), 0.5, lambda, psi);
  mean /= n;
  const Eigen::Vector3d expected = kTarget + lambda / psi / 2 * (kPosition - kTarget);
  for (int k = 0; k < 3; ++k) {
    // sd of c_k (x_k - x_t) lambda/psi is |x_k - x_t| lambda/psi / sqrt(12); plus E_i.
    const double sd =
        std::abs(kPosition[k] - kTarget[k]) * lambda / psi / std::sqrt(12.0) +
        0.5 * params.vision_sigma_depth;
    EXPECT_NEAR(mean[k], expected[k], 5 * sd / std::sqrt(n)) << "axis " << k;
  }
}

TEST(DrawEstimatedTarget, KeyedByTrialAndDecision) {
  const GuidanceParams params;
  const auto draw = [&](std::uint64_t trial, std::uint64_t decision) {
    return DrawEstimatedTarget(params, {1, trial}, decision, kTarget, kPosition,
                               Eigen::Vector3d(0, 1, 0), 0.4, 0.3, 0.9);
  };
  EXPECT_EQ(draw(3, 5), draw(3, 5));
  EXPECT_NE(draw(3, 5), draw(3, 6));
  EXPECT_NE(draw(3, 5), draw(4, 5));
}

TEST(VisionError, DeeperAlongTheSightLine) {
  const Eigen::Vector3d sight = Eigen::Vector3d(0, 1, -1).normalized();
  const Eigen::Vector3d across(1, 0, 0);
  const double eta = 0.8, sd = 0.02, sl = 0.004;
  const int n = 100000;
  double along2 = 0, across2 = 0;
  rng::Stream s({2, 0}, 0, rng::Purpose::kTest);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d z(s.Normal(), s.Normal(), s.Normal());
    const Eigen::Vector3d e = VisionError(eta, sight, sd, sl, z);
    along2 += std::pow(e.dot(sight), 2);
    across2 += std::pow(e.dot(across), 2);
  }
  along2 /= n, across2 /= n;
  const double v_along = std::pow(eta * sd, 2), v_across = std::pow(eta * sl, 2);
  EXPECT_NEAR(along2, v_along, 5 * v_along * std::sqrt(2.0 / n));
  EXPECT_NEAR(across2, v_across, 5 * v_across * std::sqrt(2.0 / n));
  EXPECT_EQ(VisionError(0.0, sight, sd, sl, Eigen::Vector3d(1, 1, 1)),
            Eigen::Vector3d::Zero());
}

TEST(FreeAssemblyForce, Eq7) {
  const Eigen::Vector3d tp(0.0, 0.0, 1.0);
  const Eigen::Vector3d f = FreeAssemblyForce(400.0, 0.9, kPosition, tp);
  EXPECT_NEAR(f.norm(), 400.0 * 0.9 * (tp - kPosition).norm(), 1e-12);  // kappa Psi D_i
  EXPECT_NEAR(f.normalized().dot((tp - kPosition).normalized()), 1.0, 1e-15);
}

TEST(ContactAssemblyForce, Eq8PerpendicularToContactPlusFriction) {
  const Eigen::Vector3d tp = kPosition + Eigen::Vector3d(0.03, 0.0, -0.04);
  const Eigen::Vector3d contact(0.0, 0.0, 5.0);  // contact pushes up
  const Eigen::Vector3d f = ContactAssemblyForce(400.0, 0.9, kPosition, tp, contact, 2.0);
  EXPECT_NEAR(f.dot(contact), 0.0, 1e-12);
  EXPECT_NEAR(f.norm(), 400.0 * 0.9 * 0.03 + 2.0, 1e-12);
  EXPECT_GT(f.x(), 0.0);
  // T_i T' along the contact normal leaves no direction to push in.
  EXPECT_EQ(ContactAssemblyForce(400.0, 0.9, kPosition,
                                 kPosition + Eigen::Vector3d(0, 0, -0.1), contact, 2.0),
            Eigen::Vector3d::Zero());
  // No contact force: Eq. 8 is Eq. 7 plus friction along the same direction.
  const Eigen::Vector3d free =
      ContactAssemblyForce(400.0, 0.9, kPosition, tp, Eigen::Vector3d::Zero(), 0.0);
  EXPECT_NEAR((free - FreeAssemblyForce(400.0, 0.9, kPosition, tp)).norm(), 0.0, 1e-12);
}

TEST(WithdrawalTarget, BackAlongTheLineFromTheTarget) {
  const Eigen::Vector3d w = WithdrawalTarget(kPosition, kTarget, 0.005);
  EXPECT_NEAR((w - kPosition).norm(), 0.005, 1e-15);
  EXPECT_NEAR((w - kTarget).norm(), (kPosition - kTarget).norm() + 0.005, 1e-15);
  EXPECT_EQ(WithdrawalTarget(kTarget, kTarget, 0.005), kTarget);  // no way to go
}

TEST(ContactBlend, C1SmoothstepFromZeroToOne) {
  EXPECT_EQ(ContactBlend(0.0, 2.0), 0.0);
  EXPECT_EQ(ContactBlend(2.0, 2.0), 1.0);
  EXPECT_EQ(ContactBlend(5.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(ContactBlend(1.0, 2.0), 0.5);
  // Zero slope at both ends (C1): one-sided differences vanish like h.
  const double h = 1e-6;
  EXPECT_LT(ContactBlend(h, 2.0) / h, 1e-5);
  EXPECT_LT((1.0 - ContactBlend(2.0 - h, 2.0)) / h, 1e-5);
}

struct ForceCase {
  GuidanceParams params;
  double psi = 0.9, mass = 0.5, blend = 0.5, fade = 1e-3;
  Eigen::Vector3d target = kPosition + Eigen::Vector3d(0.02, -0.01, -0.05);
  Eigen::Vector3d velocity{0.1, 0.0, -0.3};
  Eigen::Vector3d weight{0.0, 0.0, -0.5 * 9.80665};
  Eigen::Vector3d Force(const FeltContact& c) const {
    return ImpedanceForce(params, psi, mass, kPosition, target, velocity, c, blend,
                          weight, fade);
  }
};

// The push that overcomes friction is Eq. 8's friction itself up to half of
// max_push, then bends with equal slope towards max_push and never passes it:
// a wedged part whose friction grows with the push cannot drive it without
// bound.
TEST(FrictionPush, EqualsTheFrictionThenBendsTowardsTheBound) {
  const double m = 100.0;
  for (double f : {0.0, 1.0, 25.0, 50.0}) {
    EXPECT_EQ(FrictionPush(f, m), f);
    EXPECT_EQ(FrictionPushSlope(f, m), 1.0);
  }
  EXPECT_NEAR(FrictionPush(50.0 + 1e-9, m), 50.0 + 1e-9, 1e-12);  // continuous
  EXPECT_NEAR(FrictionPushSlope(50.0 + 1e-9, m), 1.0, 1e-9);      // and its slope
  double last = 50.0;
  for (double f : {60.0, 100.0, 1e3, 1e4}) {
    const double p = FrictionPush(f, m);
    EXPECT_GT(p, last);
    EXPECT_LT(p, m);
    EXPECT_NEAR(
        FrictionPushSlope(f, m),
        (FrictionPush(f * (1 + 1e-6), m) - FrictionPush(f * (1 - 1e-6), m)) / (2e-6 * f),
        1e-6);
    last = p;
  }
  EXPECT_NEAR(FrictionPush(1e12, m), m, 1e-8);
  EXPECT_LE(FrictionPush(1e300, m), m);
  EXPECT_EQ(FrictionPush(1e12, 0.0), 1e12);  // 0: unbounded, the paper's Eq. 8
  EXPECT_EQ(FrictionPushSlope(1e12, 0.0), 1.0);
}

TEST(ImpedanceForce, FrictionPushIsBoundedByMaxPush) {
  ForceCase k;
  k.params.max_push = 10.0;
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, 0.0, 1.0).normalized();
  const Eigen::Vector3d light = k.Force({2.0 * n, 1.0});
  const Eigen::Vector3d wedged = k.Force({2.0 * n, 1e9});
  // Only the friction push differs, along P (T' - T), by less than max_push.
  EXPECT_LT((wedged - light).norm(), k.params.max_push);
  EXPECT_GT((wedged - light).norm(), 0.5 * k.params.max_push);
}

TEST(ImpedanceForce, FreeIsEq7WithWeightSupportAndDamping) {
  const ForceCase k;
  const double b =
      2.0 * k.params.damping_ratio * std::sqrt(k.params.kappa * k.psi * k.mass);
  const Eigen::Vector3d expected =
      FreeAssemblyForce(k.params.kappa, k.psi, kPosition, k.target) -
      k.params.weight_support * k.weight - b * k.velocity;
  EXPECT_NEAR((k.Force({}) - expected).norm(), 0.0, 1e-12);
}

TEST(ImpedanceForce, FullContactIsEq8WithTheCurrentNormalAndFriction) {
  const ForceCase k;
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, 0.0, 1.0).normalized();
  const double friction = 1.5;
  const Eigen::Vector3d f = k.Force({2.0 * n, friction});  // 2 N > blend 0.5 N
  const double b =
      2.0 * k.params.damping_ratio * std::sqrt(k.params.kappa * k.psi * k.mass);
  const Eigen::Vector3d to = k.target - kPosition;
  const Eigen::Vector3d along = to - to.dot(n) * n;
  // Away from T' (|P(T' - T)| >> fade) the push is Eq. 8: kappa Psi |P(T'-T)| + f.
  const Eigen::Vector3d eq8 =
      ContactAssemblyForce(k.params.kappa, k.psi, kPosition, k.target, n, friction);
  const Eigen::Vector3d expected =
      k.params.kappa * k.psi * along +
      friction * along / std::sqrt(along.squaredNorm() + k.fade * k.fade) -
      b * k.velocity;
  EXPECT_NEAR((f - expected).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f + b * k.velocity - eq8).norm(), 1e-3 * eq8.norm(), 1e-3 * eq8.norm());
  EXPECT_NEAR((f + b * k.velocity).dot(n), 0.0, 1e-12);  // perpendicular to the normal
}

TEST(ImpedanceForce, ContinuousAsContactFormsFromAnyDirection) {
  const ForceCase k;
  const Eigen::Vector3d free = k.Force({});
  for (const Eigen::Vector3d& dir : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0),
                                     Eigen::Vector3d(-0.6, 0.8, 0.0)}) {
    for (double fn : {1e-3, 1e-5, 1e-7}) {
      // The change is of order kappa |T' - T| (fn / blend)^2 and friction alike.
      const Eigen::Vector3d f = k.Force({fn * dir, 10 * fn});
      EXPECT_LT((f - free).norm(), 200.0 * std::pow(fn / k.blend, 2) + 30 * fn)
          << "fn " << fn << " along " << dir.transpose();
    }
  }
}

TEST(ImpedanceForce, NoJumpThroughTheBlend) {
  const ForceCase k;
  const Eigen::Vector3d n = Eigen::Vector3d(0.2, -0.1, 1.0).normalized();
  const int steps = 20000;
  const double top = 2.0 * k.blend, dfn = top / steps;
  Eigen::Vector3d last = k.Force({});
  double largest = 0;
  for (int i = 1; i <= steps; ++i) {
    const double fn = i * dfn;
    const Eigen::Vector3d f = k.Force({fn * n, 0.3 * fn});  // friction grows with load
    largest = std::max(largest, (f - last).norm());
    last = f;
  }
  // A continuous law changes by O(dfn) per step: the blend's steepest slope
  // 1.5 / blend times the Eq. 7 - Eq. 8 difference (about 25 N here), plus
  // the friction term's 0.3 per newton.
  EXPECT_LT(largest, (1.5 / k.blend * 30.0 + 0.3) * dfn);
}

}  // namespace
}  // namespace vahf::guidance
