#include "vahf/sim/rigid_body_jacobian.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "vahf/core/cross_matrix.h"

namespace vahf::sim {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Block = Eigen::Matrix<double, 3, 12>;  // columns (dx, dtheta, v, w)

Eigen::Matrix<double, 3, 4> RotationOfQuaternion(const Eigen::Vector4d& q) {
  const double norm = q.norm();
  const Eigen::Vector4d n = q / norm;
  const Vector3d u = n.tail<3>();
  Eigen::Matrix<double, 3, 4> out;
  out.col(0) = -u;
  out.rightCols<3>() = n[0] * Matrix3d::Identity() + CrossMatrix(u);
  return (2.0 / norm) * out;
}

// rigid_body.h's equations term by term, with c = R com, I_w = R I R^T and
// under a world rotation dtheta: dc = dtheta x c, d(I_w x) = [dtheta]x I_w x -
// I_w [dtheta]x x for any fixed x (the product rule):
//   z = tau - c x F - w x I_w w,  alpha = I_w^-1 z,
//     d alpha = I_w^-1 (dz - d(I_w) alpha)
//   a = F / m + g - alpha x c - w x (w x c)
//   qdot = 1/2 [0, w] (x) q:  d/dq = 1/2 [[0, -w^T], [w, [w]x]],
//                             d/dw = 1/2 [-u^T; s I - [u]x] (raw q = (s, u))
BodyJacobian DerivativeJacobian(const TrialModel& model, const BodyState& y,
                                const Loads& loads, const LoadJacobian& load_jacobian,
                                const Vector3d&) {
  const Matrix3d Id = Matrix3d::Identity();
  const Eigen::Quaterniond q = Eigen::Quaterniond(y[3], y[4], y[5], y[6]).normalized();
  const Matrix3d R = q.toRotationMatrix();
  const Vector3d w = y.segment<3>(10);
  const Vector3d c = R * model.com;
  const Matrix3d I = R * model.inertia_body * R.transpose();
  const Eigen::LDLT<Matrix3d> solve = I.ldlt();
  const Vector3d& F = loads.force;
  const Vector3d Iw = I * w;
  const Vector3d alpha = solve.solve(loads.torque - c.cross(F) - w.cross(Iw));
  const Matrix3d c_x = CrossMatrix(c), w_x = CrossMatrix(w);
  // The turning of I_w applied to a fixed vector x, per dtheta.
  const auto turning = [&](const Vector3d& x) -> Matrix3d {
    return -CrossMatrix(I * x) + I * CrossMatrix(x);
  };
  const Block dF = load_jacobian.topRows<3>(), dtau = load_jacobian.bottomRows<3>();
  Block dc = Block::Zero();
  dc.block<3, 3>(0, 3) = -c_x;
  Block dz = dtau - (-CrossMatrix(F) * dc + c_x * dF);
  dz.block<3, 3>(0, 3) -= w_x * turning(w);
  dz.block<3, 3>(0, 9) -= w_x * I - CrossMatrix(Iw);
  Block rhs = dz;
  rhs.block<3, 3>(0, 3) -= turning(alpha);
  const Block dalpha = solve.solve(rhs);
  Block da = dF / model.mass + c_x * dalpha - CrossMatrix(alpha) * dc - w_x * w_x * dc;
  da.block<3, 3>(0, 9) -= -CrossMatrix(w.cross(c)) - w_x * c_x;

  // From the motion's columns to the state's: the quaternion through dtheta.
  const Eigen::Matrix<double, 3, 4> G = RotationOfQuaternion(y.segment<4>(3));
  const auto to_state = [&](const Block& b) {
    Eigen::Matrix<double, 3, kBodyStateSize> out;
    out << b.leftCols<3>(), b.block<3, 3>(0, 3) * G, b.rightCols<6>();
    return out;
  };
  BodyJacobian J = BodyJacobian::Zero();
  J.block<3, 3>(0, 7) = Id;  // pdot = v
  const double s = y[3];
  const Vector3d u = y.segment<3>(4);
  J(3, 3) = 0;
  J.block<1, 3>(3, 4) = -0.5 * w.transpose();
  J.block<3, 1>(4, 3) = 0.5 * w;
  J.block<3, 3>(4, 4) = 0.5 * w_x;
  J.block<1, 3>(3, 10) = -0.5 * u.transpose();
  J.block<3, 3>(4, 10) = 0.5 * (s * Id - CrossMatrix(u));
  J.block<3, kBodyStateSize>(7, 0) = to_state(da);
  J.block<3, kBodyStateSize>(10, 0) = to_state(dalpha);
  return J;
}

}  // namespace vahf::sim
