#include "vahf/sim/internal/frictional_contact.h"

#include <fmt/format.h>
#include <siconos/numerics/FrictionContactProblem.h>
#include <siconos/numerics/Friction_cst.h>
#include <siconos/numerics/NonSmoothDrivers.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/SolverOptions.h>
#include <siconos/numerics/SparseBlockMatrix.h>
#include <siconos/numerics/fc3d_compute_error.h>
#include <siconos/numerics/sn_error_handling.h>

#include <cmath>
#include <csetjmp>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <string>

#include "vahf/core/error.h"

// Siconos numerics 4.4 as Debian 12 ships it, read in its sources at the tag
// 4.4.0 (github.com/siconos/siconos) and probed in the library:
// - sn_error_handling.c keeps the fatal-error jump buffer, and numerics'
//   verbosity, in thread-local variables (tlsdef.h; TLS symbols in
//   `readelf -Ws libsiconos_numerics.so`): each thread has its own.
// - NSGS's default local solver (Alart and Curnier's Newton,
//   fc3d_onecontact_nonsmooth_Newton_solvers.c) keeps function pointers in
//   static variables, written by every solve: two threads would race. The
//   projection on the cone with local iterations (fc3d_projection.c) keeps
//   its state in its SolverOptions, so solves on several threads need no lock.
// - On a dense matrix NSGS's products are OpenBLAS's (cblas_ddot,
//   cblas_dgemv), and OpenBLAS splits a dgemv of 96 x 96 or more among its
//   threads: U's bits changed with OPENBLAS_NUM_THREADS (1 against 2, 100
//   contacts). On the sparse block storage (SBM) they are Siconos' own
//   loops over 3 x 3 blocks (SparseBlockMatrix.c, op3x3.h), and what is left
//   of BLAS is cblas_dnrm2 (one thread; the same x87 kernel on every x86-64
//   OpenBLAS target) and cblas_dcopy. So W goes to Siconos as 3 x 3 blocks.

// sn_fatal_error's text lives on the stack of the function that raised the
// error (numerics_error formats it in a local buffer), which the longjmp
// leaves: sn_fatal_error_msg() points there, and a call made after the
// longjmp can overwrite it (the test's RaiseFatalError message, read that
// way, came back empty). So the text is copied before the longjmp, by the
// fault handler sn_fatal_error calls first: a thread-local pointer that
// libsiconos_numerics exports but none of its headers declares
// (sn_error_handling.c).
extern "C" __thread void (*external_fault_handler)(std::size_t, const char*);

namespace vahf::sim::internal {
namespace {

// The largest problem handed to Siconos dense: OpenBLAS 0.3.21 runs a dgemv
// of m x n on one thread while m n < 9216 (interface/gemv.c: 2304 times
// GEMM_MULTITHREAD_THRESHOLD, 4) and a dgetrf while m n < 10000
// (interface/lapack/getrf.c), so up to 93 rows (31 contacts) every dense
// product and factorisation has the bits of one thread
// (kLargestDenseContacts). Larger problems go as 3 x 3 blocks, whose
// products are Siconos' own.
constexpr Eigen::Index kLargestDense = 3 * kLargestDenseContacts;

// Siconos' messages are at most this long (numerics_error's buffer).
constexpr std::size_t kMessageSize = 2048;

// The last fatal error's message on this thread.
thread_local char fatal_message[kMessageSize];

void CopyFatalMessage(std::size_t, const char* text) {
  std::size_t i = 0;
  for (; text != nullptr && text[i] != '\0' && i + 1 < kMessageSize; ++i) {
    fatal_message[i] = text[i];
  }
  fatal_message[i] = '\0';
}

// Runs f(context) with Siconos' fatal errors caught: sn_fatal_error then
// longjmps to this thread's buffer set here instead of calling abort(). The
// longjmp crosses only Siconos' C frames and f's, so no object with a
// destructor may live in f or here, and f must not throw (the buffer would
// stay set). Returns false after a fatal error, its text in fatal_message.
bool RunGuarded(void (*f)(void*), void* context) {
  fatal_message[0] = '\0';
  external_fault_handler = &CopyFatalMessage;
  if (setjmp(*sn_get_jmp_buf()) == 0) {
    f(context);
    sn_release_jmp_buf();
    external_fault_handler = nullptr;
    return true;
  }
  external_fault_handler = nullptr;
  sn_fatal_error_msg();  // forgets Siconos' pointer to the dead text
  return false;
}

[[noreturn]] void ThrowRefused() {
  throw ComputationError(ComputationError::Reason::kRefused,
                         fmt::format("SolveFrictionalContact: Siconos: {}",
                                     static_cast<const char*>(fatal_message)));
}

// Siconos frees these arrays with free(), so they come from calloc: zeroed,
// a block pointer not yet set frees nothing.
template <typename T>
T* Allocate(std::size_t count) {
  void* p = std::calloc(count, sizeof(T));
  if (p == nullptr) {
    throw ComputationError(
        ComputationError::Reason::kRefused,
        fmt::format("SolveFrictionalContact: calloc of {} x {} bytes failed", count,
                    sizeof(T)));
  }
  return static_cast<T*>(p);
}

struct MatrixDelete {
  void operator()(NumericsMatrix* m) const { NM_free(m); }
};
using MatrixPtr = std::unique_ptr<NumericsMatrix, MatrixDelete>;

// W / scale as Siconos' sparse block matrix of n x n blocks of 3 x 3, each
// column-major; every block is stored (one body couples every pair of
// contacts). The matrix owns its blocks from the first allocation on, so
// NM_free frees whatever was built when an allocation fails.
MatrixPtr NewBlockMatrix(const Eigen::MatrixXd& W, double scale) {
  const auto n = static_cast<unsigned>(W.rows() / 3);
  SparseBlockStructuredMatrix* m = SBM_new();
  MatrixPtr owner(NM_new_SBM(static_cast<int>(3 * n), static_cast<int>(3 * n), m));
  m->blocknumber0 = m->blocknumber1 = n;
  m->blocksize0 = Allocate<unsigned>(n);
  m->blocksize1 = Allocate<unsigned>(n);
  m->index1_data = Allocate<std::size_t>(n + 1);
  m->index2_data = Allocate<std::size_t>(std::size_t{n} * n);
  m->block = Allocate<double*>(std::size_t{n} * n);  // null: nothing for SBM_clear yet
  m->nbblocks = n * n;
  m->filled1 = n + 1;  // the size of index1_data: the rows of blocks, + 1
  m->filled2 = std::size_t{n} * n;
  for (unsigned i = 0; i < n; ++i) {
    m->blocksize0[i] = m->blocksize1[i] = 3 * (i + 1);  // cumulated sizes
    m->index1_data[i + 1] = std::size_t{i + 1} * n;
    for (unsigned j = 0; j < n; ++j) {
      double* block = m->block[i * n + j] = Allocate<double>(9);
      m->index2_data[i * n + j] = j;
      for (unsigned c = 0; c < 3; ++c) {
        for (unsigned r = 0; r < 3; ++r)
          block[r + 3 * c] = W(3 * i + r, 3 * j + c) / scale;
      }
    }
  }
  return owner;
}

// solver_options_delete of Siconos 4.4 frees what a SolverOptions holds, but
// neither the struct nor its internal solvers' structs (LeakSanitizer).
void DeleteOptions(SolverOptions* o) {
  if (o == nullptr) return;
  for (std::size_t i = 0; i < o->numberOfInternalSolvers; ++i) {
    DeleteOptions(o->internalSolvers[i]);
  }
  o->numberOfInternalSolvers = 0;  // solver_options_delete frees the array only
  solver_options_delete(o);
  std::free(o);
}

struct OptionsDelete {
  void operator()(SolverOptions* o) const { DeleteOptions(o); }
};
using OptionsPtr = std::unique_ptr<SolverOptions, OptionsDelete>;

// NSGS, its error evaluated in full (fc3d_compute_error) after every sweep,
// on the projection's local solver (see the top of this file).
OptionsPtr NewNsgsOptions(const FrictionalContactOptions& options) {
  OptionsPtr o(solver_options_create(SICONOS_FRICTION_3D_NSGS));
  o->dparam[SICONOS_DPARAM_TOL] = options.tolerance;
  o->iparam[SICONOS_IPARAM_MAX_ITER] = options.max_iterations;
  o->iparam[SICONOS_FRICTION_3D_IPARAM_ERROR_EVALUATION] =
      SICONOS_FRICTION_3D_NSGS_ERROR_EVALUATION_FULL;
  SolverOptions* newton = o->internalSolvers[0];
  o->internalSolvers[0] = solver_options_create(
      SICONOS_FRICTION_3D_ONECONTACT_ProjectionOnConeWithLocalIteration);
  DeleteOptions(newton);
  return o;
}

// Siconos' proximal point method (fc3d_proximal.c; its inner solver Alart
// and Curnier's nonsmooth Newton method on the whole problem, which keeps
// no static state), its tolerance and iterations the outer ones.
OptionsPtr NewProximalOptions(const FrictionalContactOptions& options) {
  OptionsPtr o(solver_options_create(SICONOS_FRICTION_3D_PROX));
  o->dparam[SICONOS_DPARAM_TOL] = options.tolerance;
  o->iparam[SICONOS_IPARAM_MAX_ITER] = options.max_iterations;
  return o;
}

// W / scale as a dense NumericsMatrix (column-major, as Eigen's).
MatrixPtr NewDenseMatrix(const Eigen::MatrixXd& W, double scale) {
  MatrixPtr m(
      NM_create(NM_DENSE, static_cast<int>(W.rows()), static_cast<int>(W.cols())));
  for (Eigen::Index k = 0; k < W.size(); ++k) m->matrix0[k] = W.data()[k] / scale;
  return m;
}

// What the guarded driver call sees: plain pointers, nothing to destroy.
struct DriverCall {
  FrictionContactProblem* problem;
  double* reaction;
  double* velocity;
  SolverOptions* options;
  int info;
};

void CallDriver(void* context) {
  auto* call = static_cast<DriverCall*>(context);
  call->info = fc3d_driver(call->problem, call->reaction, call->velocity, call->options);
}

// What the guarded error evaluation sees.
struct ErrorCall {
  FrictionContactProblem* problem;
  double* reaction;
  double* velocity;
  SolverOptions* options;
  double norm_q;
  double error;
};

void CallError(void* context) {
  auto* call = static_cast<ErrorCall*>(context);
  fc3d_compute_error(call->problem, call->reaction, call->velocity,
                     call->options->dparam[SICONOS_DPARAM_TOL], call->options,
                     call->norm_q, &call->error);
}

// The power of two next below W's largest diagonal entry, 1 when that is not
// positive. The projection's local solver starts every contact at a step of
// 1 and shrinks it by line search to about 1 / |W_ii|: unscaled, the 5 g part
// of this file's test (W's diagonal up to 1000) took 31 sweeps from its own
// solution instead of 1, its first steps throwing the reactions away.
// Dividing W by a power of two and multiplying R by it rounds nothing (short
// of underflow), so U = (W / 2^k)(2^k R) + q has the bits of W R + q.
double Scale(const Eigen::MatrixXd& W) {
  const double largest = W.diagonal().maxCoeff();
  return largest > 0 ? std::ldexp(1.0, std::ilogb(largest)) : 1.0;
}

void CheckInputs(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                 const Eigen::VectorXd& mu, const FrictionalContactOptions& options,
                 const Eigen::VectorXd* R, const Eigen::VectorXd* U) {
  VAHF_CHECK(R != nullptr && U != nullptr, "SolveFrictionalContact writes R and U");
  const Eigen::Index n = mu.size();
  VAHF_CHECK(
      W.rows() == 3 * n && W.cols() == 3 * n && q.size() == 3 * n && R->size() == 3 * n,
      fmt::format("SolveFrictionalContact: {} contacts need W of {} x {}, q and R of "
                  "{}, not W {} x {}, q {}, R {}",
                  n, 3 * n, 3 * n, 3 * n, W.rows(), W.cols(), q.size(), R->size()));
  VAHF_CHECK((mu.array() >= 0).all() && mu.allFinite(),
             "SolveFrictionalContact: friction coefficients are finite and >= 0");
  VAHF_CHECK(options.max_iterations >= 1 && options.tolerance > 0,
             "SolveFrictionalContact: at least 1 sweep, a positive tolerance");
  if (!W.allFinite() || !q.allFinite() || !R->allFinite()) {
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        "SolveFrictionalContact: W, q or the first R holds a value that "
        "is not finite");
  }
}

}  // namespace

FrictionalContactResult SolveFrictionalContact(const Eigen::MatrixXd& W,
                                               const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& mu,
                                               const FrictionalContactOptions& options,
                                               Eigen::VectorXd* R, Eigen::VectorXd* U) {
  CheckInputs(W, q, mu, options, R, U);
  FrictionalContactResult result;
  U->setZero(q.size());
  if (q.size() == 0) {
    result.converged = true;
    return result;
  }
  const double scale = Scale(W);
  const bool proximal = options.method == FrictionalContactOptions::kProximalPoint;
  // Dense products below OpenBLAS's threading thresholds (top of this file).
  const bool dense = proximal && q.size() <= kLargestDense;
  MatrixPtr matrix = dense ? NewDenseMatrix(W, scale) : NewBlockMatrix(W, scale);
  OptionsPtr solver = proximal ? NewProximalOptions(options) : NewNsgsOptions(options);
  Eigen::VectorXd q_copy = q, mu_copy = mu;  // Siconos takes them non-const
  FrictionContactProblem problem;
  problem.dimension = 3;
  problem.numberOfContacts = static_cast<int>(mu.size());
  problem.M = matrix.get();
  problem.q = q_copy.data();
  problem.mu = mu_copy.data();
  *R *= scale;
  DriverCall call{&problem, R->data(), U->data(), solver.get(), -1};
  if (!RunGuarded(&CallDriver, &call)) {
    *R /= scale;
    ThrowRefused();
  }
  result.iterations = solver->iparam[SICONOS_IPARAM_ITER_DONE];
  result.error = solver->dparam[SICONOS_DPARAM_RESIDU];
  result.converged = call.info == 0;
  if (proximal) {
    // PROX adds and takes away its regularisation on W's diagonal, which
    // rounds, and leaves `info` unset when its first guess already solves
    // the problem: its answer is judged on the problem as given.
    matrix = dense ? NewDenseMatrix(W, scale) : NewBlockMatrix(W, scale);
    q_copy = q;
    problem.M = matrix.get();
    ErrorCall check{&problem, R->data(), U->data(), solver.get(), q.norm(), 0.0};
    if (!RunGuarded(&CallError, &check)) {
      *R /= scale;
      ThrowRefused();
    }
    result.error = check.error;
    result.converged = check.error <= options.tolerance;
  }
  *R /= scale;
  if (!result.converged) {
    result.detail = fmt::format(
        "Siconos' frictional contact solve ({}) of {} contacts did not converge: error "
        "{:.3g} after {} iterations, tolerance {:.3g}",
        proximal ? "PROX" : "NSGS", mu.size(), result.error, result.iterations,
        options.tolerance);
  }
  return result;
}

void RunGuardedForTest(void (*f)()) {
  struct TestCall {
    void (*f)();
  } call{f};
  if (!RunGuarded([](void* context) { static_cast<TestCall*>(context)->f(); }, &call)) {
    ThrowRefused();
  }
}

}  // namespace vahf::sim::internal
