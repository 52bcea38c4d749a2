#include "vahf/experiment/instants.h"

#include "vahf/human/factors.h"

namespace vahf::experiment {

double TiltDeg(const sim::TraceRow& row, const Eigen::Matrix3d& target_rotation) {
  return human::AngleDeg(row.orientation.toRotationMatrix().col(2),
                         target_rotation.col(2));
}

Instants FindInstants(const sim::TrialResult& trial,
                      const Eigen::Matrix3d& target_rotation,
                      double completion_angle_deg) {
  Instants out;
  if (trial.status == sim::Status::kCompleted) out.d = trial.final_row;
  const auto& rows = trial.trace;
  std::size_t first = rows.size();
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (rows[k].contact_force.norm() > 0) {
      first = k;
      break;
    }
  if (first == rows.size()) return out;
  out.a = rows[first];
  std::size_t widest = first;
  for (std::size_t k = first; k < rows.size(); ++k)
    if (rows[k].contact_force.norm() > 0 &&
        TiltDeg(rows[k], target_rotation) > TiltDeg(rows[widest], target_rotation))
      widest = k;
  out.b = rows[widest];
  for (std::size_t k = widest + 1; k < rows.size(); ++k)
    if (TiltDeg(rows[k], target_rotation) < completion_angle_deg) {
      out.c = rows[k];
      break;
    }
  return out;
}

}  // namespace vahf::experiment
