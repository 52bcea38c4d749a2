// Which parameters a fit's targets determine (docs/calibration.md,
// "Identifiability"). Two tests, after Raue et al., "Structural and practical
// identifiability analysis of partially observed dynamical models by
// exploiting the profile likelihood", Bioinformatics 25(15), 2009:
//
// - structural: the whitened Jacobian of the residuals at the estimate, its
//   columns scaled by the parameters' magnitudes (so that the test does not
//   depend on units), has a null space: a direction in which no target moves
//   within a difference step. A singular value counts as zero below
//   kRankTolerance of the largest: the reciprocal condition number 1e-14 of
//   J^T J at which Ceres' covariance refuses to invert
//   (ceres::Covariance::Options::min_reciprocal_condition_number), on J's
//   singular values. A parameter with more than kNullWeight of its unit
//   direction in the null space is not identified.
// - practical: the cost, moved along one parameter from the estimate to a
//   bound (the others held), rises by less than chi^2_1(0.95) / 2: then the
//   profile (which re-fits the others, so lies lower) rises less too, and
//   the 95 % profile region reaches that bound. Open at both bounds, the
//   data do not determine the parameter within them.
//
// A parameter not identified gets no interval; the others' covariance is
// then that of the identified ones with the rest held at their estimates.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace vahf::calibrate {

inline constexpr double kRankTolerance = 1e-7;
inline constexpr double kNullWeight = 0.1;

struct JacobianRank {
  int rank = 0;
  Eigen::VectorXd singular_values;  // of J diag(scale), descending
  // s_1 / s_rank: how much worse the worst identified direction is
  // determined than the best; infinite at rank 0.
  double condition = 0;
  std::vector<bool> in_null_space;  // per parameter (kNullWeight)
};

// `jacobian` m x p (whitened residuals by parameters), `scale` p positive
// magnitudes. A zero or non-finite Jacobian has rank 0.
JacobianRank RankOf(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& scale);

// The covariance (J_I^T J_I)^-1 of the parameters in `identified`, the
// others held: NaN rows and columns for the rest, and all NaN when J_I is
// itself rank deficient (kRankTolerance on its scaled singular values).
Eigen::MatrixXd ConditionalCovariance(const Eigen::MatrixXd& jacobian,
                                      const Eigen::VectorXd& scale,
                                      const std::vector<bool>& identified);

// The correlation matrix of a covariance: NaN where a variance is not
// positive and finite.
Eigen::MatrixXd Correlation(const Eigen::MatrixXd& covariance);

}  // namespace vahf::calibrate
