// The free body's equations of motion (rigid_body.h) against closed forms:
// with no load the centre of mass falls with g whatever the spin and the
// offset of the centre from the origin; a torque-free spin about a principal
// axis keeps its rate; a pure torque about the centre gives I alpha = tau; a
// force through the centre gives a = F / m without turning; the quaternion
// rate turns the frame by w; and StateOf and MotionOf are inverse.
#include "vahf/sim/rigid_body.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "vahf/scene/parameters.h"

namespace vahf::sim {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kG = 9.80665;

// A body of 2 kg, principal inertia diag(0.01, 0.02, 0.03) about a centre of
// mass 5 cm off its origin, turned 30 deg about an oblique axis.
human::FactorCurves Curves() {
  const scene::Parameters p;  // the defaults: the curves play no part here
  return {p.sight.Build(), p.reach.Build(0.74, 1.75), p.glance.Build()};
}

struct Body {
  TrialModel model{Curves()};
  contact::RigidMotion motion;
  Body() {
    model.mass = 2.0;
    model.com = Vector3d(0.05, -0.02, 0.03);
    model.inertia_body = Vector3d(0.01, 0.02, 0.03).asDiagonal();
    motion.pose.linear() =
        Eigen::AngleAxisd(M_PI / 6, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    motion.pose.translation() = Vector3d(0.1, 0.2, 0.9);
  }
  Matrix3d R() const { return motion.pose.linear(); }
};

// The centre of mass's acceleration from the origin's (a) and alpha.
Vector3d CentreAcceleration(const Body& b, const BodyState& dy) {
  const Vector3d c = b.R() * b.model.com;
  const Vector3d w = b.motion.angular_velocity;
  return dy.segment<3>(7) + dy.segment<3>(10).cross(c) + w.cross(w.cross(c));
}

TEST(RigidBody, StateAndMotionAreInverse) {
  Body b;
  b.motion.velocity = {0.3, -0.1, 0.2};
  b.motion.angular_velocity = {1.0, -2.0, 0.5};
  const contact::RigidMotion m = MotionOf(StateOf(b.motion));
  EXPECT_LT((m.pose.matrix() - b.motion.pose.matrix()).norm(), 1e-15);
  EXPECT_EQ(m.velocity, b.motion.velocity);
  EXPECT_EQ(m.angular_velocity, b.motion.angular_velocity);
}

TEST(RigidBody, UnloadedCentreFallsWithGWhateverTheSpin) {
  Body b;
  b.motion.velocity = {0.3, -0.1, 0.2};
  b.motion.angular_velocity = {1.0, -2.0, 0.5};
  const Vector3d g(0, 0, -kG);
  const BodyState dy = Derivative(b.model, StateOf(b.motion), Loads{}, g);
  EXPECT_LT((CentreAcceleration(b, dy) - g).norm(), 1e-12);
  EXPECT_EQ(Vector3d(dy.segment<3>(0)), b.motion.velocity);
  // Euler's equations: the angular momentum about the centre is constant.
  const Matrix3d I = b.R() * b.model.inertia_body * b.R().transpose();
  const Vector3d w = b.motion.angular_velocity;
  EXPECT_LT((I * dy.segment<3>(10) + w.cross(I * w)).norm(), 1e-14);
}

TEST(RigidBody, TorqueFreeSpinAboutAPrincipalAxisKeepsItsRate) {
  Body b;
  b.motion.angular_velocity = 3.0 * b.R().col(2);  // about the body z axis
  const BodyState dy = Derivative(b.model, StateOf(b.motion), Loads{}, Vector3d::Zero());
  EXPECT_LT(Vector3d(dy.segment<3>(10)).norm(), 1e-13);
}

TEST(RigidBody, TorqueAboutTheCentreTurnsByTheInverseInertia) {
  Body b;
  const Vector3d tau(0.01, -0.02, 0.005);  // about the centre of mass
  Loads loads;
  // The same couple stated about the origin: a couple is the same about any point.
  loads.torque = tau;
  const BodyState dy = Derivative(b.model, StateOf(b.motion), loads, Vector3d::Zero());
  const Matrix3d I = b.R() * b.model.inertia_body * b.R().transpose();
  EXPECT_LT((I * dy.segment<3>(10) - tau).norm(), 1e-14);
  EXPECT_LT(CentreAcceleration(b, dy).norm(),
            1e-12);  // a couple does not move the centre
}

TEST(RigidBody, ForceThroughTheCentreAcceleratesWithoutTurning) {
  Body b;
  const Vector3d F(3.0, -1.0, 2.0);
  const Vector3d c = b.R() * b.model.com;
  Loads loads;
  loads.force = F;            // at the origin,
  loads.torque = c.cross(F);  // plus its moment: the same force acting at the centre
  const BodyState dy = Derivative(b.model, StateOf(b.motion), loads, Vector3d::Zero());
  EXPECT_LT(Vector3d(dy.segment<3>(10)).norm(), 1e-14);
  EXPECT_LT((CentreAcceleration(b, dy) - F / b.model.mass).norm(), 1e-13);
}

TEST(RigidBody, QuaternionRateTurnsTheFrameByOmega) {
  Body b;
  b.motion.angular_velocity = {0.4, -0.7, 1.1};
  const BodyState y = StateOf(b.motion);
  const BodyState dy = Derivative(b.model, y, Loads{}, Vector3d::Zero());
  const double h = 1e-7;
  const BodyState ahead = y + h * dy;
  const Matrix3d expected = Eigen::AngleAxisd(h * b.motion.angular_velocity.norm(),
                                              b.motion.angular_velocity.normalized())
                                .toRotationMatrix() *
                            b.R();
  EXPECT_LT((MotionOf(ahead).pose.linear() - expected).norm(), 1e-12);
}

}  // namespace
}  // namespace vahf::sim
