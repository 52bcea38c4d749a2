// The free moving body's equations of motion without Simbody, for steppers
// other than Simbody's (docs/design.md decision 13). State, world frame:
//   y = [p (3), q (4: w, x, y, z), v (3), w (3)]
// p the body origin, q the unit quaternion of the part frame, v the origin's
// velocity, w the angular velocity (Simbody's Free mobilizer, same meaning).
// Newton-Euler about the centre of mass c (part frame: TrialModel::com), with
// the loads F at the origin and tau about it:
//   tau_c = tau - (R c) x F
//   I_w alpha = tau_c - w x I_w w,        I_w = R I R^T about c
//   a_c = F / m + g
//   a = a_c - alpha x (R c) - w x (w x (R c))
//   qdot = 1/2 [0, w] q,  pdot = v
#pragma once

#include <Eigen/Core>

#include "vahf/contact/contact_model.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim {

inline constexpr int kBodyStateSize = 13;
using BodyState = Eigen::Matrix<double, kBodyStateSize, 1>;

// The state of a body at pose and velocities m (its quaternion with w >= 0).
BodyState StateOf(const contact::RigidMotion& m);
// The motion a state stands for (its quaternion normalised).
contact::RigidMotion MotionOf(const BodyState& y);
// y scaled so that its quaternion has unit length.
void NormaliseQuaternion(BodyState* y);

// dy/dt for the model's body under `loads` (at MotionOf(y)) and gravity g.
BodyState Derivative(const TrialModel& model, const BodyState& y, const Loads& loads,
                     const Eigen::Vector3d& gravity);

}  // namespace vahf::sim
