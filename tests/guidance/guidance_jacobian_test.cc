// The operator's force and torque derivatives (guidance_jacobian.h) against
// central differences of ImpedanceForce and AssemblyTorque: out of contact,
// within the contact blend and in full contact (the friction push within and
// beyond its fade length), and the torque's rotation and rate partials at a
// small, a moderate and a large orientation error; the inverse right Jacobian
// against differences of the rotation log.
#include "vahf/guidance/guidance_jacobian.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "support/motion_differences.h"
#include "vahf/guidance/assembly_torque.h"

namespace vahf::guidance {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kMass = 0.12, kFade = 1e-3;
const Vector3d kWeight(0, 0, -kMass * 9.80665);
const double kBlend = 0.1 * kMass * 9.80665;

struct Felt {
  Vector3d position, target, velocity, normal_force;
  double friction;
};

Vector3d Force(const GuidanceParams& g, const Felt& s) {
  return ImpedanceForce(g, 0.9, kMass, s.position, s.target, s.velocity,
                        {s.normal_force, s.friction}, kBlend, kWeight, kFade);
}

// d F / d(position, velocity, normal force, friction), 3 x 10, by differences.
Eigen::MatrixXd Differences(const GuidanceParams& g, const Felt& s) {
  Eigen::MatrixXd out(3, 10);
  const double h[4] = {1e-8, 1e-7, 1e-8, 1e-8};
  for (int j = 0; j < 10; ++j) {
    Felt up = s, down = s;
    const double e = h[j / 3];
    const auto move = [&](Felt& f, double by) {
      if (j < 3)
        f.position[j] += by;
      else if (j < 6)
        f.velocity[j - 3] += by;
      else if (j < 9)
        f.normal_force[j - 6] += by;
      else
        f.friction += by;
    };
    move(up, e);
    move(down, -e);
    out.col(j) = (Force(g, up) - Force(g, down)) / (2 * e);
  }
  return out;
}

Eigen::MatrixXd Analytic(const GuidanceParams& g, const Felt& s) {
  const ImpedancePartials p =
      ImpedanceForceJacobian(g, 0.9, kMass, s.position, s.target, s.velocity,
                             {s.normal_force, s.friction}, kBlend, kWeight, kFade);
  Eigen::MatrixXd out(3, 10);
  out << p.position, p.velocity, p.normal_force, p.friction;
  return out;
}

TEST(GuidanceJacobian, ImpedanceForceAcrossTheBlend) {
  GuidanceParams g;
  g.weight_support = 0.8;
  const Vector3d direction = Vector3d(0.3, -0.2, 1.0).normalized();
  // |P (T' - T)| about 2 mm (beyond the 1 mm fade) and 0.5 mm (within it).
  for (const Vector3d& target :
       {Vector3d(0.002, 0.0005, -0.01), Vector3d(0.0004, 0.0003, -0.01)})
    // Out of contact, 0.4 and 0.9 of the blend force, and 3 times it.
    for (double share : {0.0, 0.4, 0.9, 3.0}) {
      const Felt s{Vector3d(0.001, -0.002, 0.003), target, Vector3d(0.05, -0.02, -0.3),
                   share * kBlend * direction, 0.7 * share * kBlend};
      EXPECT_TRUE(vahf::testing::BlocksAgree(Analytic(g, s), Differences(g, s), 1e-6))
          << "share " << share << " target " << target.transpose();
    }
}

// The friction push past half of max_push, where FrictionPush bends towards
// its bound: 0.8 and 1.5 times max_push of friction.
TEST(GuidanceJacobian, ImpedanceForceWithTheFrictionPushBounded) {
  GuidanceParams g;
  g.max_push = 2.0 * kBlend;
  const Vector3d direction = Vector3d(0.3, -0.2, 1.0).normalized();
  for (double friction : {0.8 * g.max_push, 1.5 * g.max_push}) {
    const Felt s{Vector3d(0.001, -0.002, 0.003), Vector3d(0.002, 0.0005, -0.01),
                 Vector3d(0.05, -0.02, -0.3), 3.0 * kBlend * direction, friction};
    EXPECT_TRUE(vahf::testing::BlocksAgree(Analytic(g, s), Differences(g, s), 1e-6))
        << "friction " << friction;
  }
}

TEST(GuidanceJacobian, InverseRightJacobianLinearisesTheLog) {
  for (const Vector3d& theta : {Vector3d(1e-7, -2e-7, 0.0), Vector3d(0.2, -0.1, 0.25),
                                Vector3d(1.5, 1.2, -1.0)}) {
    const Matrix3d E =
        Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix();
    Matrix3d differences;
    const double h = 1e-7;
    for (int j = 0; j < 3; ++j) {
      const auto log = [&](double e) {
        const Eigen::AngleAxisd a(
            E * Eigen::AngleAxisd(e, Vector3d::Unit(j)).toRotationMatrix());
        return Vector3d(a.angle() * a.axis());
      };
      differences.col(j) = (log(h) - log(-h)) / (2 * h);
    }
    EXPECT_LT((InverseRightJacobian(theta) - differences).norm(), 1e-7)
        << theta.transpose();
  }
}

TEST(GuidanceJacobian, AssemblyTorqueRotationAndRate) {
  const GuidanceParams g;
  const Matrix3d body = Vector3d(2e-3, 3e-3, 1e-3).asDiagonal();
  const Matrix3d R =
      Eigen::AngleAxisd(0.7, Vector3d(1, -1, 2).normalized()).toRotationMatrix();
  const Vector3d omega(0.4, -1.1, 0.3);
  for (double error : {0.0, 0.3, 2.5}) {
    const Matrix3d held =
        Eigen::AngleAxisd(error, Vector3d(2, 1, -1).normalized()).toRotationMatrix() * R;
    const auto torque = [&](const contact::RigidMotion& m) -> Eigen::VectorXd {
      const Matrix3d r = m.pose.linear();
      return AssemblyTorque(g, 0.9, r * body * r.transpose(), r, held,
                            m.angular_velocity);
    };
    contact::RigidMotion m;
    m.pose.linear() = R;
    m.angular_velocity = omega;
    const Eigen::MatrixXd differences =
        vahf::testing::MotionDifferences(torque, m, {1e-7, 1e-7, 1e-7, 1e-7});
    const TorquePartials t =
        AssemblyTorqueJacobian(g, 0.9, R * body * R.transpose(), R, held, omega);
    Eigen::MatrixXd analytic = Eigen::MatrixXd::Zero(3, 12);
    analytic.block<3, 3>(0, 3) = t.rotation;
    analytic.block<3, 3>(0, 9) = t.omega;
    EXPECT_TRUE(vahf::testing::BlocksAgree(analytic, differences, 1e-6)) << error;
  }
}

}  // namespace
}  // namespace vahf::guidance
