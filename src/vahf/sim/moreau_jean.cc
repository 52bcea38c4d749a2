#include "vahf/sim/internal/moreau_jean.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "vahf/core/cross_matrix.h"

namespace vahf::sim::internal {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

namespace {

// The body at the step's start in the step's coordinates.
struct Start {
  Matrix3d R;
  Vector3d c;  // origin to centre of mass, world
  Matrix3d I;  // about the centre of mass, world
  Vector6d u;  // (v_c, w)
  Matrix6d M;
};

Start StartOf(const BodyInertia& body, const BodyState& y) {
  Start s;
  const Eigen::Quaterniond q = Eigen::Quaterniond(y[3], y[4], y[5], y[6]).normalized();
  s.R = q.toRotationMatrix();
  s.c = s.R * body.com;
  s.I = s.R * body.inertia_body * s.R.transpose();
  const Vector3d v = y.segment<3>(7), w = y.segment<3>(10);
  s.u << v + w.cross(s.c), w;
  s.M.setZero();
  s.M.topLeftCorner<3, 3>() = body.mass * Matrix3d::Identity();
  s.M.bottomRightCorner<3, 3>() = s.I;
  return s;
}

// The smooth generalised force at the centre of mass, f = (F + m g,
// tau - c x F - w x I w), and its derivative in the step's coordinates
// (dx_c, dtheta, v_c, w): the loads' columns are the origin's, whose
// displacement is dx_c + c x dtheta and velocity v_c + c x w. The derivative
// of c and of the gyroscopic term is left out (the step stays consistent;
// they are not stiff).
void Generalised(const BodyInertia& body, const Start& s, const SmoothLoads& loads,
                 const Vector3d& gravity, Vector6d* f, Matrix6d* K, Matrix6d* C) {
  const Vector3d w = s.u.tail<3>();
  *f << loads.force + body.mass * gravity,
      loads.torque - s.c.cross(loads.force) - w.cross(s.I * w);
  Eigen::Matrix<double, 6, 12> A;
  A.topRows<3>() = loads.jacobian.topRows<3>();
  A.bottomRows<3>() =
      loads.jacobian.bottomRows<3>() - CrossMatrix(s.c) * loads.jacobian.topRows<3>();
  const Matrix3d cx = CrossMatrix(s.c);
  Eigen::Matrix<double, 12, 12> T = Eigen::Matrix<double, 12, 12>::Identity();
  T.block<3, 3>(0, 3) = cx;
  T.block<3, 3>(6, 9) = cx;
  const Eigen::Matrix<double, 6, 12> Au = A * T;
  *K = Au.leftCols<6>();
  *C = Au.rightCols<6>();
}

// The rows of H for each point: normal, tangent 1, tangent 2, each
// (d, r_c x d) for the point's arm r_c from the centre of mass.
Eigen::MatrixXd ContactRows(const Start& s,
                            const std::vector<contact::ContactPoint>& points) {
  Eigen::MatrixXd H(3 * points.size(), 6);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vector3d arm = points[i].r - s.c;
    Vector3d d[3];
    d[0] = points[i].normal;
    TangentBasis(d[0], &d[1], &d[2]);
    for (int k = 0; k < 3; ++k) {
      H.block<1, 3>(3 * i + k, 0) = d[k].transpose();
      H.block<1, 3>(3 * i + k, 3) = arm.cross(d[k]).transpose();
    }
  }
  return H;
}

// The body's state after the step: the centre of mass and the orientation
// moved by u_theta over h, the velocities u+.
BodyState EndState(const BodyInertia& body, const BodyState& y, const Start& s,
                   const Vector6d& u_theta, const Vector6d& u_plus, double h) {
  const Vector3d x_c = y.segment<3>(0) + s.c + h * u_theta.head<3>();
  const Vector3d turn = h * u_theta.tail<3>();
  const double angle = turn.norm();
  Eigen::Quaterniond q = Eigen::Quaterniond(y[3], y[4], y[5], y[6]).normalized();
  if (angle > 0) q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, turn / angle)) * q;
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Vector3d c_plus = q.toRotationMatrix() * body.com;
  const Vector3d w = u_plus.tail<3>();
  BodyState out;
  out << x_c - c_plus, q.w(), q.x(), q.y(), q.z(), u_plus.head<3>() - w.cross(c_plus), w;
  return out;
}

}  // namespace

void TangentBasis(const Vector3d& n, Vector3d* t1, Vector3d* t2) {
  // The world axis least along n, crossed with it.
  int axis = 0;
  if (std::abs(n.y()) < std::abs(n[axis])) axis = 1;
  if (std::abs(n.z()) < std::abs(n[axis])) axis = 2;
  *t1 = n.cross(Vector3d::Unit(axis)).normalized();
  *t2 = n.cross(*t1);
}

MoreauJeanStepResult MoreauJeanStep(const BodyInertia& body, const BodyState& y, double h,
                                    const SmoothLoads& loads, const Vector3d& gravity,
                                    const std::vector<contact::ContactPoint>& points,
                                    const MoreauJeanSettings& settings,
                                    const Eigen::VectorXd* warm) {
  const Start s = StartOf(body, y);
  Vector6d f;
  Matrix6d K, C;
  Generalised(body, s, loads, gravity, &f, &K, &C);
  const double theta = settings.theta;
  const Matrix6d W_hat = s.M - h * theta * C - h * h * theta * theta * K;
  const Eigen::PartialPivLU<Matrix6d> lu(W_hat);
  const Vector6d u_free = s.u + lu.solve(h * (f + h * theta * (K * s.u)));
  MoreauJeanStepResult out;
  Vector6d u_plus = u_free;
  out.solve.converged = true;
  if (!points.empty()) {
    const Eigen::MatrixXd H = ContactRows(s, points);
    const Eigen::MatrixXd X = lu.solve(H.transpose());  // W_hat^-1 H^T
    Eigen::MatrixXd W = H * X;
    const double c = settings.compliance * W.diagonal().mean();
    Eigen::VectorXd q = H * u_free;
    Eigen::VectorXd mu(points.size());
    const double e = settings.restitution, h_o = std::max(h, settings.overlap_step);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double un = H.row(3 * i).dot(s.u), g = points[i].gap;
      if (g + h * un <= 0)
        q[3 * i] += e * un + std::min(g, 0.0) / h_o;
      else
        q[3 * i] += g >= 0 ? g / h : g / h_o;
      W(3 * i, 3 * i) += c;
      mu[i] = points[i].mu;
    }
    out.reactions =
        warm && warm->size() == q.size() ? *warm : Eigen::VectorXd::Zero(q.size());
    Eigen::VectorXd U(q.size());
    out.solve = SolveFrictionalContact(W, q, mu, settings.solver, &out.reactions, &U);
    u_plus += X * out.reactions;
    // The impulses along H's directions (its rows' first three columns).
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d P = out.reactions.segment<3>(3 * i);
      const auto d = H.block<3, 3>(3 * i, 0);
      out.normal_impulse += P[0] * d.row(0).transpose();
      out.friction_impulse += P[1] * d.row(1).transpose() + P[2] * d.row(2).transpose();
      if (P[0] > 0) ++out.loaded_points;
    }
  }
  const Vector6d u_theta = (1 - theta) * s.u + theta * u_plus;
  out.y = EndState(body, y, s, u_theta, u_plus, h);
  return out;
}

}  // namespace vahf::sim::internal
