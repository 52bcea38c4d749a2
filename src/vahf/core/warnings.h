// A trial's record of numerical trouble, in the spirit of MuJoCo's
// mjData.warning (docs/design.md decision 12), and of the part's rests,
// where the contact's friction law rather than the operator sets the time
// (issue 53): for each kind, how often it happened, when first, and what
// was seen then. Experiments sum the records of their trials; a test fails
// on any warning it did not expect.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace vahf {

enum class WarningKind {
  kNonFiniteState,     // a force evaluation or accepted step saw NaN or infinity
  kPenetrationBound,   // an accepted step's contact was deeper than the bound
  kStepSizeFloor,      // an accepted step was shorter than simulation/step_floor
  kIntegratorRetry,    // the integrator failed a convergence or realization and retried
  kIntegratorFailure,  // the integrator gave up (the trial is a numerical failure)
  kContactSolver,      // a nonsmooth step's contact problem ended unconverged
  kRest,               // the part rested in contact (sim/rest_watch.h): once a rest
};
inline constexpr int kWarningKinds = 7;

// Short machine name: non_finite_state, penetration_bound, step_size_floor,
// integrator_retry, integrator_failure, contact_solver, rest.
const char* WarningName(WarningKind kind);

struct WarningEntry {
  std::int64_t count = 0;
  double first_time = -1;  // s of simulated time; -1 while count is 0
  std::string detail;      // what was seen at first_time
};

class Warnings {
 public:
  // Counts `n` occurrences at `time`; the first one's time and detail stay.
  void Note(WarningKind kind, double time, const std::string& detail,
            std::int64_t n = 1) {
    Count(
        kind, time, [&] { return detail; }, n);
  }
  // The same, with the detail made by `detail()` only for the first
  // occurrence (a warning met at every step formats its text once).
  template <class Detail>
  void Count(WarningKind kind, double time, const Detail& detail, std::int64_t n = 1) {
    if (n <= 0) return;
    WarningEntry& e = entries_[static_cast<int>(kind)];
    if (e.count == 0) {
      e.first_time = time;
      e.detail = detail();
    }
    e.count += n;
  }
  // Adds another record: counts add, the earlier first occurrence stays (for
  // sums over trials the times are of different trials; the first in
  // summation order is kept).
  void Add(const Warnings& other);

  const WarningEntry& at(WarningKind kind) const {
    return entries_[static_cast<int>(kind)];
  }
  std::int64_t total() const;
  bool empty() const { return total() == 0; }
  // "none", or "penetration_bound 3 (first at t = 0.12 s: ...); ..."
  std::string Summary() const;

 private:
  std::array<WarningEntry, kWarningKinds> entries_;
};

}  // namespace vahf
