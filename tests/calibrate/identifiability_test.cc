// Rank, null space and the conditional covariance of a whitened Jacobian.
#include "vahf/calibrate/identifiability.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vahf::calibrate {
namespace {

TEST(Identifiability, AColumnNoResidualMovesIsInTheNullSpace) {
  Eigen::MatrixXd j(3, 3);
  j << 1, 0, 2,  //
      0, 0, 1,   //
      3, 0, 0;
  const JacobianRank r = RankOf(j, Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(r.rank, 2);
  EXPECT_EQ(r.singular_values(2), 0.0);
  EXPECT_FALSE(r.in_null_space[0]);
  EXPECT_TRUE(r.in_null_space[1]);
  EXPECT_FALSE(r.in_null_space[2]);
}

TEST(Identifiability, TwoParametersOnlyTheirSumMovesAreBothNotIdentified) {
  Eigen::MatrixXd j(3, 3);
  j << 1, 1, 5,  //
      2, 2, 0,   //
      -1, -1, 1;
  const JacobianRank r = RankOf(j, Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(r.rank, 2);
  EXPECT_TRUE(r.in_null_space[0]);
  EXPECT_TRUE(r.in_null_space[1]);
  EXPECT_FALSE(r.in_null_space[2]);
}

TEST(Identifiability, TheRankDoesNotDependOnUnits) {
  // The second parameter in units 1e9 times smaller: its column 1e-9 as
  // large, the scale 1e9 times larger.
  Eigen::MatrixXd j(2, 2);
  j << 1, 2e-9,  //
      3, -1e-9;
  EXPECT_EQ(RankOf(j, Eigen::Vector2d(1, 1e9)).rank, 2);
  EXPECT_EQ(RankOf(j, Eigen::Vector2d(1, 1)).rank, 1);
}

TEST(Identifiability, TheCovarianceOfAllIsTheInverseOfJtJ) {
  Eigen::MatrixXd j(3, 2);
  j << 1, 2,  //
      0, 1,   //
      4, -1;
  const Eigen::MatrixXd c =
      ConditionalCovariance(j, Eigen::Vector2d(2, 0.5), {true, true});
  const Eigen::MatrixXd expected = (j.transpose() * j).inverse();
  EXPECT_LT((c - expected).norm(), 1e-12 * expected.norm());
}

TEST(Identifiability, TheOthersAreHeldWhereOneIsNotIdentified) {
  Eigen::MatrixXd j(3, 2);
  j << 1, 0,  //
      2, 0,   //
      2, 0;
  const Eigen::MatrixXd c =
      ConditionalCovariance(j, Eigen::Vector2d(1, 1), {true, false});
  EXPECT_NEAR(c(0, 0), 1.0 / 9.0, 1e-15);
  EXPECT_TRUE(std::isnan(c(1, 1)));
  EXPECT_TRUE(std::isnan(c(0, 1)));
  const Eigen::MatrixXd rho = Correlation(c);
  EXPECT_EQ(rho(0, 0), 1.0);
  EXPECT_TRUE(std::isnan(rho(1, 0)));
}

}  // namespace
}  // namespace vahf::calibrate
