#include "vahf/calibrate/identifiability.h"

#include <Eigen/SVD>
#include <cmath>
#include <limits>

namespace vahf::calibrate {

JacobianRank RankOf(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& scale) {
  const Eigen::Index p = jacobian.cols();
  JacobianRank out;
  out.in_null_space.assign(static_cast<std::size_t>(p), true);
  out.singular_values = Eigen::VectorXd::Zero(p);
  out.condition = std::numeric_limits<double>::infinity();
  if (p == 0 || !jacobian.allFinite() || !scale.allFinite()) return out;
  const Eigen::MatrixXd scaled = jacobian * scale.asDiagonal();
  // Full V: the null space's directions are its last columns, also when
  // there are fewer residuals than parameters.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();  // min(m, p), descending
  out.singular_values.head(s.size()) = s;
  if (s.size() == 0 || !(s(0) > 0)) return out;
  while (out.rank < s.size() && s(out.rank) > kRankTolerance * s(0)) ++out.rank;
  out.condition = s(0) / s(out.rank - 1);
  const Eigen::MatrixXd null = svd.matrixV().rightCols(p - out.rank);
  for (Eigen::Index i = 0; i < p; ++i)
    out.in_null_space[static_cast<std::size_t>(i)] =
        null.cols() > 0 && null.row(i).norm() > kNullWeight;
  return out;
}

Eigen::MatrixXd ConditionalCovariance(const Eigen::MatrixXd& jacobian,
                                      const Eigen::VectorXd& scale,
                                      const std::vector<bool>& identified) {
  const Eigen::Index p = jacobian.cols();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(p, p, nan);
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < p; ++i)
    if (identified[static_cast<std::size_t>(i)]) keep.push_back(i);
  const Eigen::Index k = static_cast<Eigen::Index>(keep.size());
  if (k == 0) return out;
  Eigen::MatrixXd j(jacobian.rows(), k);
  Eigen::VectorXd d(k);
  for (Eigen::Index c = 0; c < k; ++c) {
    j.col(c) = jacobian.col(keep[static_cast<std::size_t>(c)]);
    d(c) = scale(keep[static_cast<std::size_t>(c)]);
  }
  if (RankOf(j, d).rank < k) return out;
  // In scaled coordinates, for its conditioning: C = D (A^T A)^-1 D with
  // A = J D, by the SVD A = U S V^T: (A^T A)^-1 = V S^-2 V^T.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j * d.asDiagonal(), Eigen::ComputeThinV);
  const Eigen::MatrixXd v = svd.matrixV();
  const Eigen::VectorXd inv2 = svd.singularValues().array().square().inverse();
  const Eigen::MatrixXd c =
      d.asDiagonal() * (v * inv2.asDiagonal() * v.transpose()) * d.asDiagonal();
  for (Eigen::Index a = 0; a < k; ++a)
    for (Eigen::Index b = 0; b < k; ++b)
      out(keep[static_cast<std::size_t>(a)], keep[static_cast<std::size_t>(b)]) = c(a, b);
  return out;
}

Eigen::MatrixXd Correlation(const Eigen::MatrixXd& covariance) {
  const Eigen::Index p = covariance.rows();
  Eigen::MatrixXd out(p, p);
  for (Eigen::Index i = 0; i < p; ++i)
    for (Eigen::Index j = 0; j < p; ++j) {
      const double vi = covariance(i, i), vj = covariance(j, j);
      out(i, j) = std::isfinite(vi) && std::isfinite(vj) && vi > 0 && vj > 0
                      ? covariance(i, j) / std::sqrt(vi * vj)
                      : std::numeric_limits<double>::quiet_NaN();
    }
  return out;
}

}  // namespace vahf::calibrate
