// The Jacobian d(dy/dt)/dy of the free body's equations of motion
// (rigid_body.h) for implicit steppers: exact derivative of Derivative(model,
// y, loads(y), g) as CVODE integrates it, the quaternion entering the loads
// and the Newton-Euler terms through MotionOf's normalisation and qdot
// through the raw quaternion.
#pragma once

#include <Eigen/Core>

#include "vahf/sim/rigid_body.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim {

using BodyJacobian = Eigen::Matrix<double, kBodyStateSize, kBodyStateSize>;

// d Derivative / dy at y, with `loads` = the loads at MotionOf(y) and
// `load_jacobian` their derivative w.r.t. the motion (TrialModel::LoadsAt).
BodyJacobian DerivativeJacobian(const TrialModel& model, const BodyState& y,
                                const Loads& loads, const LoadJacobian& load_jacobian,
                                const Eigen::Vector3d& gravity);

// d dtheta / dq: the world rotation vector of a change dq of the state's raw
// quaternion q, through its normalisation (MotionOf): with q/|q| = (s, u),
//   dtheta = 2 / |q| [-u | s I + [u]x] dq
// (the vector part of 2 dq q*, the tangential part of dq; the radial part
// does not turn the frame).
Eigen::Matrix<double, 3, 4> RotationOfQuaternion(const Eigen::Vector4d& q);

}  // namespace vahf::sim
