// Where a trial's time goes, measured only when asked (TrialOptions::
// time_phases) for the benchmarks' cost breakdown (bench/
// trial_seeds_benchmark.cc). Steady-clock seconds (about 20 ns a reading):
// a breakdown is CPU only on a core the trial has to itself, as tools/bench
// runs it. Never part of a result's bits.
#pragma once

#include <chrono>

namespace vahf::sim {

struct PhaseSeconds {
  // Contact evaluations without their derivative: right-hand sides, the
  // accepted steps' depth checks, samples and decisions.
  double contact = 0;
  // Analytic Jacobians (CVODE): the contact's pass with its derivative, the
  // operator's derivative and the rigid body's.
  double jacobian = 0;
  // The stepper's linear solver (CVODE's dense LU): factorisations and solves.
  double linear_algebra = 0;
  // The operator's hand: its force and torque on the part at each
  // right-hand side (TrialModel::OperatorLoad), after the contact it reads.
  double hand = 0;
  // The operator's decisions (Eq. 5's draws, the human factors, fatigue, the
  // outcome checks), their contact evaluation and V's ray casting aside.
  double decisions = 0;
  // Eq. 1's ray casting, at the decisions and the final row.
  double visibility = 0;
};

// Adds the steady-clock time from its construction to its destruction to
// *into; nothing, not even a clock reading, when into is null.
class PhaseTimer {
 public:
  explicit PhaseTimer(double* into) : into_(into) {
    if (into_) start_ = Clock::now();
  }
  ~PhaseTimer() {
    if (into_) *into_ += std::chrono::duration<double>(Clock::now() - start_).count();
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  using Clock = std::chrono::steady_clock;
  double* into_;
  Clock::time_point start_{};
};

}  // namespace vahf::sim
