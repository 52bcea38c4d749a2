// What one trial returns: how it ended and why, when, the work it took, and a
// trace with one row per decision instant (a result is an object with a
// status, not an exception or a sentinel).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "vahf/core/warnings.h"
#include "vahf/human/factors.h"
#include "vahf/rng/stream.h"
#include "vahf/sim/phase_seconds.h"

namespace vahf::sim {

enum class Status {
  kCompleted,         // |T - T_t| < d_th and the angle to the target < its threshold
  kTimeout,           // the time limit passed first
  kExhausted,         // Psi_c fell to its floor (Eq. 6)
  kUnreachable,       // the part lay beyond D3 from the operator's shoulder
  kJammed,            // in contact with no progress for jam_time
  kNumericalFailure,  // NaN in the state or the integrator failed: a failure of
                      // the computation, never counted as a failed assembly
  kStepBudget,        // the work budget (simulation/max_steps accepted steps or
                      // max_contact_tests contact tests) spent before any other
                      // ending: a failure of the computation, like kNumericalFailure
};

const char* StatusName(Status status);

// A failure of the computation (numerical failure, step budget), never counted
// as a failed assembly: statistics of success and time leave it out.
bool IsComputationFailure(Status status);

struct TraceRow {
  double time = 0;                                     // s
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // T, part origin, world, m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // of the origin, m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s
  Eigen::Vector3d assembly_force = Eigen::Vector3d::Zero();    // N
  Eigen::Vector3d contact_force = Eigen::Vector3d::Zero();     // normal part, N
  Eigen::Vector3d friction_force = Eigen::Vector3d::Zero();    // N
  human::FactorValues factors;
  double work = 0;         // A, J (Eq. 4, accumulated)
  double psi = 1;          // Psi_c (Eq. 6)
  double penetration = 0;  // deepest contact point, m
};

struct TrialCounters {
  std::int64_t decisions = 0;
  std::int64_t steps_taken = 0;
  std::int64_t steps_attempted = 0;
  std::int64_t error_test_failures = 0;
  std::int64_t realizations = 0;
  // CVODE only: Jacobian evaluations (analytic or by difference quotients,
  // whose right-hand sides count as realizations) and nonlinear (Newton)
  // convergence failures.
  std::int64_t jacobian_evaluations = 0;
  std::int64_t convergence_failures = 0;
  std::int64_t contact_evaluations = 0;
  std::int64_t contact_point_queries = 0;
  std::int64_t contact_tests = 0;  // queries and edges examined, ContactCounters::Tests
  std::int64_t broad_phase_skips = 0;
  std::int64_t clusters_skipped = 0;
  std::int64_t rays_cast = 0;
  std::int64_t shell_points = 0;
};

// What a trial's rests came to (rest_watch.h: a rest is the part in contact
// and slower than simulation/rest_speed for simulation/rest_time or longer).
struct RestSummary {
  std::int64_t count = 0;
  double total_time = 0;  // s, summed over the rests counted
  double longest = 0;     // s
  // Times the operator withdrew a part that had rested guidance/stall_time.
  std::int64_t withdrawals = 0;

  void Add(double duration);
};

struct TrialResult {
  Status status = Status::kTimeout;
  std::string detail;           // why it ended; where, for a failure
  double end_time = 0;          // simulated s
  double completion_time = -1;  // s, for status completed
  // s: the first decision instant (simulation/decision_interval apart) at
  // which the part touched a fixed part with a normal force; -1 if it never
  // did. From it to completion_time is the insertion proper, the part at the
  // hole (docs/handbooks.md, "Virtual insertion time").
  double first_contact_time = -1;
  std::string part;  // the assembling part
  std::string integrator;
  double accuracy = 0;
  rng::StreamKey key;
  TrialCounters counters;
  double wall_seconds = 0;  // measured, never part of a digest
  double cpu_seconds = 0;   // this thread's CPU, measured, never part of a digest
  PhaseSeconds phases;      // with TrialOptions::time_phases; never part of a digest
  double work = 0;          // A when the trial ended, J (Eq. 4, with the initial work)
  std::vector<TraceRow> trace;  // one row per decision instant (if recorded)
  // One row per sample instant (TrialOptions::sample_interval).
  std::vector<TraceRow> samples;
  // Numerical health: what went wrong at accepted steps, and how deep the
  // contact went against the bound (penetration_fraction of the smallest
  // radial clearance between the part at its target and a fixed part).
  Warnings warnings;
  double max_penetration = 0;    // m, over accepted steps, decisions and samples
  double penetration_bound = 0;  // m; 0 when the scene has no radial fit
  double clearance = 0;          // m; 0 when the scene has no radial fit
  // The contact's stiffnesses as the trial used them (contact/model):
  // face law Pa/m, line law Pa; 0 when nothing can be touched (the line law:
  // when the contact model has no rims).
  double stiffness = 0, line_stiffness = 0;
  // The part's rests, each also a `rest` warning with its start, duration
  // and place.
  RestSummary rests;
  // The part, its factors and A at the instant the trial ended (for a
  // completion, the completion instant: paper Table 1's instant d). Always set.
  TraceRow final_row;

  std::string BriefReport() const;
};

}  // namespace vahf::sim
