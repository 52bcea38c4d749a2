// The per-step 3-D frictional contact problem of a nonsmooth stepper, solved
// by Siconos numerics 4.4 (fc3d; V. Acary and B. Brogliato, Numerical Methods
// for Nonsmooth Dynamical Systems, 2008), in its local form: for n
// contacts, each with 3 rows (normal, tangent 1, tangent 2),
//   U = W R + q,
//   R_i in the Coulomb cone K_i = {r : |r_t| <= mu_i r_n},
//   U_i + mu_i |U_t,i| e_n in its dual cone, orthogonal to R_i
// (De Saxce's modified velocity: G. De Saxce and Z.-Q. Feng, Math. Comput.
// Modelling 28 (1998) 225-245), W square (3n x 3n), q and R of size 3n.
//
// The solver is Siconos' proximal point method or its nonsmooth Gauss-Seidel
// (NSGS) over the contacts, each contact's problem solved by projection on
// its cone with local iterations (FrictionalContactOptions::method); the
// error is Siconos' fc3d_compute_error, relative.
// Deterministic: the same inputs give the same bits on any thread, whatever
// the number of OpenBLAS threads, and calls on several threads at once need
// no lock (frictional_contact.cc says why).
#pragma once

#include <Eigen/Core>
#include <string>

namespace vahf::sim::internal {

// The most contacts a problem may have to be solved dense, where OpenBLAS
// runs every product and factorisation on one thread whatever its thread
// count (frictional_contact.cc): 31, 93 rows. Larger problems go to Siconos'
// sparse path, about ten times slower.
inline constexpr int kLargestDenseContacts = 31;

struct FrictionalContactOptions {
  // Siconos' proximal point method (fc3d_proximal.c: Alart and Curnier's
  // nonsmooth Newton method on a proximal regularisation of the problem,
  // the regularisation driven to zero; the default), or its nonsmooth
  // Gauss-Seidel over the contacts (NSGS). On the piston rod's problems
  // (6-32 contacts on one rigid body, W of rank 6) NSGS stalled on 25 of 194
  // at 1000 sweeps; the proximal point method solved all 194 to 1e-10 in
  // 8.7 iterations on average, in about the same time (docs/physics.md,
  // "Nonsmooth stepping").
  enum Method { kProximalPoint, kGaussSeidel };
  Method method = kProximalPoint;
  // Siconos' relative error (fc3d_compute_error) below which the solve has
  // converged: the natural map's residual over max(|q|, |R|, |U|).
  double tolerance = 1e-10;
  int max_iterations = 1000;  // PROX's outer iterations or NSGS's sweeps, at least 1
};

struct FrictionalContactResult {
  bool converged = false;
  int iterations =
      0;  // PROX iterations or NSGS sweeps; 0 when no q_n < -DBL_EPSILON: R = 0, U = q
  double error = 0;    // Siconos' error at the end, of the problem as solved (below)
  std::string detail;  // when not converged: the iterations and the error, in words
};

// Solves the problem for R and U. R comes in as the first guess (a warm
// start: the previous step's reactions, or zeros) and must have size 3n; U
// is resized. Solved as U = (W / 2^k)(2^k R) + q, 2^k the power of two next
// below W's largest diagonal entry, which rounds nothing and makes the
// local solver's first step fit W's scale (frictional_contact.cc).
// An unconverged solve is a result (converged false), not an error. Sizes
// that disagree, a friction coefficient that is negative or not finite, no
// sweep allowed or a tolerance <= 0 are a caller's bug (VAHF_CHECK). Throws
// ComputationError kOutOfDomain when W, q or the incoming R holds a value
// that is not finite, kRefused with Siconos' message when Siconos meets a
// fatal error (sn_fatal_error), which it would otherwise answer with abort().
FrictionalContactResult SolveFrictionalContact(const Eigen::MatrixXd& W,
                                               const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& mu,
                                               const FrictionalContactOptions& options,
                                               Eigen::VectorXd* R, Eigen::VectorXd* U);

// For the tests: runs f under the guard SolveFrictionalContact puts around
// Siconos, so a fatal error raised in f (sn_fatal_error) throws
// ComputationError kRefused with its message instead of aborting.
void RunGuardedForTest(void (*f)());

}  // namespace vahf::sim::internal
