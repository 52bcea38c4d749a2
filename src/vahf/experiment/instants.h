// The instants of paper Table 1 / Fig. 9 in one part's trial:
//   a  first contact with the assembled parts;
//   b  non-equilibrium: the largest tilt of the part's axis from its target
//      axis while in contact (at or after a);
//   c  moment equilibrium, realigned: the first instant after b at which the
//      tilt is back below the completion angle;
//   d  completion.
// a, b and c are read at decision instants (the trace), d at the completion
// instant (TrialResult::final_row). An instant the trial never reached is
// absent: a part that completes without touching anything has no a, b or c.
#pragma once

#include <optional>

#include "vahf/sim/trial_result.h"

namespace vahf::experiment {

struct Instants {
  std::optional<sim::TraceRow> a, b, c, d;
};

// Tilt of the part's z axis from the target's, degrees.
double TiltDeg(const sim::TraceRow& row, const Eigen::Matrix3d& target_rotation);

// `completion_angle_deg` is the scene's simulation/completion_angle_deg.
Instants FindInstants(const sim::TrialResult& trial,
                      const Eigen::Matrix3d& target_rotation,
                      double completion_angle_deg);

}  // namespace vahf::experiment
