// SolveFrictionalContact (sim/internal/frictional_contact.h), Siconos' NSGS
// on the 3-D frictional contact problem U = W R + q, R_i in the Coulomb cone,
// U_i + mu_i |U_t,i| e_n in its dual, orthogonal to R_i (De Saxce and Feng
// 1998; Acary and Brogliato 2008, Ch. 13). The oracles:
// - closed forms of one contact with W = I (separating, sticking, sliding)
//   and of two contacts at one point of a point mass, whose sum is the one
//   contact of that mass, however the rank-deficient W splits it;
// - on a 30-contact body, the conditions themselves, evaluated here with
//   this file's own projection on the cones, within the bounds the solve's
//   reported error implies;
// - the law that results do not depend on the threads: the same bits twice
//   and on two threads at once;
// - Siconos' fatal error raised through its own sn_fatal_error.
#include "vahf/sim/internal/frictional_contact.h"

#include <gtest/gtest.h>
#include <siconos/numerics/sn_error_handling.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "vahf/core/error.h"

namespace vahf::sim::internal {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// The closed forms hold to the solve's relative error (1e-10 of |q| <= 2.3)
// times W = I's condition (1) and the cone's Lipschitz constant (1 + mu):
// below 1e-9. 1e-8 leaves a factor of 10.
constexpr double kClose = 1e-8;

struct Solution {
  VectorXd R, U;
  FrictionalContactResult result;
};

Solution Solve(const MatrixXd& W, const VectorXd& q, const VectorXd& mu,
               FrictionalContactOptions options = {}, VectorXd R = VectorXd()) {
  Solution s;
  s.R = R.size() == 0 ? VectorXd::Zero(q.size()) : R;
  s.result = SolveFrictionalContact(W, q, mu, options, &s.R, &s.U);
  return s;
}

void ExpectNear(const VectorXd& actual, const VectorXd& expected, double tolerance) {
  ASSERT_EQ(actual.size(), expected.size());
  for (Eigen::Index i = 0; i < actual.size(); ++i) {
    EXPECT_NEAR(actual[i], expected[i], tolerance) << "entry " << i;
  }
}

VectorXd Vec(std::initializer_list<double> values) {
  VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v[i++] = x;
  return v;
}

// One contact, W = I, mu = 1/2. With W = I, U = R + q.
TEST(FrictionalContact, OneContactSeparating) {
  // q_n >= 0: R = 0 satisfies every condition (U = q in the dual cone), and
  // Siconos returns it without a sweep, whatever R came in.
  const Solution s =
      Solve(MatrixXd::Identity(3, 3), Vec({1, 0, 0}), Vec({0.5}), {}, Vec({3, 1, 0}));
  EXPECT_TRUE(s.result.converged);
  EXPECT_EQ(s.result.iterations, 0);
  EXPECT_EQ(s.R, Vec({0, 0, 0}));
  EXPECT_EQ(s.U, Vec({1, 0, 0}));
}

TEST(FrictionalContact, OneContactSticking) {
  // Sticking: U = 0, so R = -q = (1, -0.1, 0), inside the cone (0.1 < mu * 1);
  // U's modified velocity 0 is in the dual cone and orthogonal to R.
  const Solution s = Solve(MatrixXd::Identity(3, 3), Vec({-1, 0.1, 0}), Vec({0.5}));
  EXPECT_TRUE(s.result.converged) << s.result.detail;
  ExpectNear(s.R, Vec({1, -0.1, 0}), kClose);
  ExpectNear(s.U, Vec({0, 0, 0}), kClose);
}

TEST(FrictionalContact, OneContactSliding) {
  // Sliding: R on the cone's edge against the slip, R_t = -mu R_n U_t / |U_t|.
  // Orthogonality of R to U + mu |U_t| e_n gives R_n U_n + mu R_n |U_t| -
  // mu R_n |U_t| = R_n U_n = 0, so U_n = 0, R_n = -q_n = 1, and with
  // U_t = q_t + R_t, U_t = q_t (1 - mu / |q_t|). For q_t = (2, 0):
  // R = (1, -0.5, 0), U = (0, 1.5, 0); for q_t = (1.2, 1.6), |q_t| = 2:
  // R = (1, -0.3, -0.4), U = (0, 0.9, 1.2).
  const MatrixXd I = MatrixXd::Identity(3, 3);
  const Solution along = Solve(I, Vec({-1, 2, 0}), Vec({0.5}));
  EXPECT_TRUE(along.result.converged) << along.result.detail;
  ExpectNear(along.R, Vec({1, -0.5, 0}), kClose);
  ExpectNear(along.U, Vec({0, 1.5, 0}), kClose);
  const Solution oblique = Solve(I, Vec({-1, 1.2, 1.6}), Vec({0.5}));
  EXPECT_TRUE(oblique.result.converged) << oblique.result.detail;
  ExpectNear(oblique.R, Vec({1, -0.3, -0.4}), kClose);
  ExpectNear(oblique.U, Vec({0, 0.9, 1.2}), kClose);
}

// A point mass m (3 DOF) meets a plane at two contacts at one point, both in
// the frame (z, x, y): J = [S; S], S taking (v_x, v_y, v_z) to (v_z, v_x,
// v_y), W = J J^T / m, 6 x 6 of rank 3, so the split of R between the two is
// not unique. Their sum P = R_1 + R_2 is: U_1 = U_2 = P / m + q_1, and P is
// in the cone, U's modified velocity in the dual, P orthogonal to it, so P
// solves the one contact of W = I / m, whose solution is unique.
TEST(FrictionalContact, TwoContactsAtOnePointSumToOne) {
  const double m = 2;  // kg
  MatrixXd S = MatrixXd::Zero(3, 3);
  S(0, 2) = S(1, 0) = S(2, 1) = 1;
  MatrixXd J(6, 3);
  J << S, S;
  const MatrixXd W = J * J.transpose() / m;
  const VectorXd mu = Vec({0.5, 0.5});
  // Sliding, v = (2, 0, -1) m/s: stopping the slip needs m 2 = 4 N s, more
  // than mu P_n = 0.5 m 1 = 1, so P = (2, -1, 0) and U_t = 2 - 1 / m = 1.5.
  // Sticking, v = (0.1, 0, -1): P = -m q = (2, -0.2, 0), U = 0.
  struct Case {
    VectorXd v, P, U;
  };
  for (const Case& c : {Case{Vec({2, 0, -1}), Vec({2, -1, 0}), Vec({0, 1.5, 0})},
                        Case{Vec({0.1, 0, -1}), Vec({2, -0.2, 0}), Vec({0, 0, 0})}}) {
    const Solution s = Solve(W, J * c.v, mu);
    EXPECT_TRUE(s.result.converged) << s.result.detail;
    ExpectNear(s.R.head<3>() + s.R.tail<3>(), c.P, kClose);
    ExpectNear(s.U.head<3>(), c.U, kClose);
    ExpectNear(s.U.tail<3>(), c.U, kClose);
  }
}

// A 5 g body (a disc of 1 cm radius) lands turning and sliding on a plane at
// 30 contact points of its underside: W = J M^-1 J^T of rank 6, its diagonal
// up to about 1000 (1 / m = 200, and the turning), friction 0.2 to 0.5.
struct BodyProblem {
  MatrixXd W;
  VectorXd q, mu;
};

BodyProblem ThirtyContacts(double mu_offset = 0, int n = 30) {
  const double m = 0.005, inertia_xy = 1.3e-7, inertia_z = 2.5e-7;  // kg, kg m^2
  MatrixXd J(3 * n, 6);
  for (int i = 0; i < n; ++i) {
    const double radius = 0.01 * std::sqrt((i + 0.5) / n), angle = 2.39996 * i;
    const Eigen::Vector3d p(radius * std::cos(angle), radius * std::sin(angle), -0.004);
    const Eigen::Vector3d d[3] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                  Eigen::Vector3d::UnitY()};
    for (int k = 0; k < 3; ++k) {
      J.block<1, 3>(3 * i + k, 0) = d[k].transpose();
      J.block<1, 3>(3 * i + k, 3) = p.cross(d[k]).transpose();  // d . (w x p)
    }
  }
  VectorXd inverse_mass(6);
  inverse_mass << 1 / m, 1 / m, 1 / m, 1 / inertia_xy, 1 / inertia_xy, 1 / inertia_z;
  VectorXd v(6);
  v << 0.05, -0.02, -0.3, 2, -1, 5;  // m/s, rad/s
  BodyProblem b;
  b.W = J * inverse_mass.asDiagonal() * J.transpose();
  b.q = J * v;
  b.mu.resize(n);
  for (int i = 0; i < n; ++i) b.mu[i] = 0.2 + 0.15 * (i % 3) + mu_offset;
  return b;
}

// The projection on K_mu = {x : |x_t| <= mu x_n}, written here apart from
// Siconos': x itself inside the cone, 0 inside its polar (mu |x_t| <= -x_n),
// else the nearest point of the cone's edge in the plane of x and the axis.
Eigen::Vector3d ProjectOnCone(const Eigen::Vector3d& x, double mu) {
  const double t = x.tail<2>().norm();
  if (t <= mu * x[0]) return x;
  if (mu * t <= -x[0]) return Eigen::Vector3d::Zero();
  const double n = (x[0] + mu * t) / (1 + mu * mu);
  Eigen::Vector3d p;
  p << n, mu * n * x.tail<2>() / t;
  return p;
}

// The conditions, from the error e that Siconos reports, relative to
// s = max(|q|, |R'|, |U|) of the problem as solved (R' = 2^k R, the header's
// 2^k): the natural map's residual r_i = R'_i - P_K(R'_i - Uhat_i) has |r_i|
// <= e s. Split z = R'_i - Uhat_i = P_K(z) + P_N(z), N = -K* the polar cone,
// the two parts orthogonal (J.-J. Moreau, C. R. Acad. Sci. Paris 255 (1962)
// 238-240): then Uhat_i = r_i - P_N(z), -P_N(z) in the dual cone K* and
// orthogonal to P_K(z) = R'_i - r_i. So R'_i is within |r_i| of K, Uhat_i
// within |r_i| of K* (= K_1/mu), and |R'_i . Uhat_i| <= |r_i| (|R'_i| +
// |Uhat_i| + 3 |r_i|).
void ExpectSolves(const BodyProblem& b, const Solution& s) {
  const double scale = std::ldexp(1.0, std::ilogb(b.W.diagonal().maxCoeff()));
  const VectorXd R = scale * s.R;
  const double size = std::max({b.q.norm(), R.norm(), s.U.norm()});
  const double r = s.result.error * size;
  // U against W R + q summed here in another order: each sum of n + 1 terms (n its rows)
  // is within gamma_(n+1) = (n + 1) u / (1 - (n + 1) u) of its terms' absolute sum, u the
  // unit roundoff (N. J. Higham, Accuracy and Stability of Numerical
  // Algorithms, 2nd ed. (2002), Sec. 3.1).
  const double terms_in_sum = static_cast<double>(b.W.cols() + 1);
  const double u = std::numeric_limits<double>::epsilon() / 2,
               gamma = terms_in_sum * u / (1 - terms_in_sum * u);
  const VectorXd terms = b.W.cwiseAbs() * s.R.cwiseAbs() + b.q.cwiseAbs();
  EXPECT_TRUE(
      ((s.U - (b.W * s.R + b.q)).cwiseAbs().array() <= 2 * gamma * terms.array()).all());
  for (Eigen::Index i = 0; i < b.mu.size(); ++i) {
    const Eigen::Vector3d Ri = R.segment<3>(3 * i);
    Eigen::Vector3d Uhat = s.U.segment<3>(3 * i);
    Uhat[0] += b.mu[i] * Uhat.tail<2>().norm();
    EXPECT_LE((Ri - ProjectOnCone(Ri, b.mu[i])).norm(), r) << "contact " << i;
    EXPECT_LE((Uhat - ProjectOnCone(Uhat, 1 / b.mu[i])).norm(), r) << "contact " << i;
    EXPECT_LE(std::abs(Ri.dot(Uhat)), r * (Ri.norm() + Uhat.norm() + 3 * r))
        << "contact " << i;
  }
}

TEST(FrictionalContact, ThirtyContactsMeetTheConditions) {
  const BodyProblem b = ThirtyContacts();
  const Solution s = Solve(b.W, b.q, b.mu);
  ASSERT_TRUE(s.result.converged) << s.result.detail;
  EXPECT_LE(s.result.error, FrictionalContactOptions{}.tolerance);
  ExpectSolves(b, s);
}

// The other paths: Gauss-Seidel (NSGS, on 3 x 3 blocks), and the proximal
// point method past the dense limit (40 contacts, on 3 x 3 blocks).
TEST(FrictionalContact, GaussSeidelAndTheSparsePathMeetTheConditions) {
  const BodyProblem b = ThirtyContacts();
  FrictionalContactOptions gauss_seidel;
  gauss_seidel.method = FrictionalContactOptions::kGaussSeidel;
  const Solution s = Solve(b.W, b.q, b.mu, gauss_seidel);
  ASSERT_TRUE(s.result.converged) << s.result.detail;
  ExpectSolves(b, s);
  const BodyProblem large = ThirtyContacts(0, kLargestDenseContacts + 9);
  const Solution sparse = Solve(large.W, large.q, large.mu);
  ASSERT_TRUE(sparse.result.converged) << sparse.result.detail;
  ExpectSolves(large, sparse);
}

TEST(FrictionalContact, WarmStartFromTheSolutionTakesAtMostTwoSweeps) {
  const BodyProblem b = ThirtyContacts();
  const Solution cold = Solve(b.W, b.q, b.mu);
  ASSERT_TRUE(cold.result.converged) << cold.result.detail;
  const Solution warm = Solve(b.W, b.q, b.mu, {}, cold.R);
  ASSERT_TRUE(warm.result.converged) << warm.result.detail;
  EXPECT_LE(warm.result.iterations, 2);
  EXPECT_LT(warm.result.iterations, cold.result.iterations);
  ExpectSolves(b, warm);
}

TEST(FrictionalContact, UnconvergedIsAResultWithADetail) {
  const BodyProblem b = ThirtyContacts();
  FrictionalContactOptions options;
  options.max_iterations = 1;
  const Solution s = Solve(b.W, b.q, b.mu, options);
  EXPECT_FALSE(s.result.converged);
  EXPECT_EQ(s.result.iterations, 1);
  EXPECT_GT(s.result.error, options.tolerance);
  EXPECT_NE(s.result.detail.find("30 contacts did not converge"), std::string::npos)
      << s.result.detail;
  EXPECT_NE(s.result.detail.find("after 1 iterations"), std::string::npos)
      << s.result.detail;
}

bool SameBits(const VectorXd& a, const VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

TEST(FrictionalContact, SameBitsTwiceAndOnTwoThreadsAtOnce) {
  // Two problems, one a thread, each solved 20 times while the other runs.
  const BodyProblem problems[2] = {ThirtyContacts(), ThirtyContacts(0.1)};
  Solution alone[2];
  for (int k = 0; k < 2; ++k) {
    alone[k] = Solve(problems[k].W, problems[k].q, problems[k].mu);
    const Solution again = Solve(problems[k].W, problems[k].q, problems[k].mu);
    EXPECT_TRUE(SameBits(again.R, alone[k].R) && SameBits(again.U, alone[k].U));
  }
  int differing[2] = {0, 0};
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k) {
    threads.emplace_back([&, k] {
      for (int repeat = 0; repeat < 20; ++repeat) {
        const Solution s = Solve(problems[k].W, problems[k].q, problems[k].mu);
        if (!SameBits(s.R, alone[k].R) || !SameBits(s.U, alone[k].U)) ++differing[k];
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(differing[0], 0);
  EXPECT_EQ(differing[1], 0);
}

TEST(FrictionalContact, NotFiniteInputIsOutOfDomain) {
  VectorXd R = VectorXd::Zero(3), U;
  try {
    SolveFrictionalContact(MatrixXd::Identity(3, 3), Vec({-1, NAN, 0}), Vec({0.5}), {},
                           &R, &U);
    FAIL() << "no error";
  } catch (const ComputationError& e) {
    EXPECT_EQ(e.reason(), ComputationError::Reason::kOutOfDomain);
    EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
  }
}

// As Siconos' numerics_error does: the message formatted on the stack of
// the function that raises it, which the guard's longjmp leaves.
template <int kThread>
void RaiseFatalError() {
  char message[64];
  std::snprintf(message, sizeof message, "fatal error %d of the test", kThread);
  sn_fatal_error(SN_UNKOWN_ERROR, message);
}

std::string FatalErrorOf(void (*raise)()) {
  try {
    RunGuardedForTest(raise);
  } catch (const ComputationError& e) {
    if (e.reason() != ComputationError::Reason::kRefused) return "not kRefused";
    return e.what();
  }
  return "no error";
}

TEST(FrictionalContact, FatalErrorThrowsWithSiconosMessage) {
  const std::string expected =
      "SolveFrictionalContact: Siconos: fatal error 1 of the test";
  EXPECT_EQ(FatalErrorOf(&RaiseFatalError<1>), expected);
  EXPECT_EQ(FatalErrorOf(&RaiseFatalError<1>), expected);  // the guard is set again
  // Each thread's buffer and message are its own.
  std::string seen[2];
  std::thread other([&] {
    for (int i = 0; i < 200 && seen[1].empty(); ++i) {
      const std::string m = FatalErrorOf(&RaiseFatalError<2>);
      if (m != "SolveFrictionalContact: Siconos: fatal error 2 of the test") seen[1] = m;
    }
  });
  for (int i = 0; i < 200 && seen[0].empty(); ++i) {
    const std::string m = FatalErrorOf(&RaiseFatalError<1>);
    if (m != expected) seen[0] = m;
  }
  other.join();
  EXPECT_EQ(seen[0], "");
  EXPECT_EQ(seen[1], "");
  // And a solve after them is as before.
  const Solution s = Solve(MatrixXd::Identity(3, 3), Vec({-1, 2, 0}), Vec({0.5}));
  EXPECT_TRUE(s.result.converged);
  ExpectNear(s.R, Vec({1, -0.5, 0}), kClose);
}

}  // namespace
}  // namespace vahf::sim::internal
