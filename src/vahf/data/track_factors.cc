#include "vahf/data/track_factors.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <string>

#include "vahf/core/error.h"
#include "vahf/human/operator_model.h"

namespace vahf::data {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string Where(const TrackSample& s) { return fmt::format("line {}", s.line); }

std::string Point(const Eigen::Vector3d& p) {
  return fmt::format("({}, {}, {})", p.x(), p.y(), p.z());
}

// The sensors of one sample as the simulation's posture (Sec. 5.1).
human::Posture PostureAt(const SensorTrack& track, const TrackSample& s) {
  const Eigen::Vector3d across = s.right_shoulder - s.left_shoulder;
  const Eigen::Vector3d down = s.body - 0.5 * (s.left_shoulder + s.right_shoulder);
  // The shoulders' labels say which side is front: right minus left, crossed
  // with the way down the trunk, points forward (for an upright operator facing
  // +x: -y cross -z = +x).
  const Eigen::Vector3d facing = across.cross(down);
  // BodyPlaneFrom's own precondition, checked here so that a bad track is an
  // input error and not an abort.
  if (!(across.norm() > 0 && facing.norm() > 1e-12 * across.norm() * down.norm()))
    throw InputError(track.file, Where(s),
                     fmt::format("shoulders {} and {}, body {}", Point(s.left_shoulder),
                                 Point(s.right_shoulder), Point(s.body)),
                     "the shoulders and the body centre are collinear: they span no "
                     "body plane for g (Sec. 5.1)");
  if (!((s.part - s.brow).norm() > 0))
    throw InputError(track.file, Where(s), fmt::format("brow = part = {}", Point(s.part)),
                     "the brow and the part's centre coincide: no sight line for f "
                     "and g (Sec. 5.1)");
  human::Posture p;
  p.eye = s.brow;
  p.left_shoulder = s.left_shoulder;
  p.right_shoulder = s.right_shoulder;
  p.body_centre = s.body;
  human::BodyPlaneFrom(s.left_shoulder, s.right_shoulder, s.body, facing, &p.forward,
                       &p.down);
  return p;
}

}  // namespace

std::vector<TrackFactors> FactorsFromTrack(const SensorTrack& track,
                                           const human::FactorCurves& curves,
                                           const TrackFactorOptions& options) {
  VAHF_CHECK(std::isnan(options.visibility) ||
                 (options.visibility >= 0.0 && options.visibility <= 1.0),
             "TrackFactorOptions::visibility must be NaN or in [0, 1]");
  VAHF_CHECK(options.still_distance >= 0.0 && std::isfinite(options.still_distance),
             "TrackFactorOptions::still_distance must be finite and >= 0");
  std::vector<TrackFactors> out;
  if (track.samples.size() < 2) return out;
  out.reserve(track.samples.size() - 1);
  bool have_direction = false;
  Eigen::Vector3d direction = Eigen::Vector3d::Constant(kNaN);
  for (std::size_t i = 1; i < track.samples.size(); ++i) {
    const TrackSample& s = track.samples[i];
    TrackFactors row;
    row.time = s.time;
    row.line = s.line;
    // Sec. 5.1: "the motion direction of assembling part at time i was
    // (P_i - P_{i-1}) / |P_i - P_{i-1}|". A part that has not moved has none; the
    // operator's view of a paused part is judged against the way it was last
    // going, so that direction is carried on. (The simulation, which knows the
    // target, falls back to the way to it instead; a track does not know it.)
    const Eigen::Vector3d step = s.part - track.samples[i - 1].part;
    if (step.norm() > options.still_distance) {  // still_distance >= 0: > 0 too
      direction = step.normalized();
      have_direction = true;
      row.motion = MotionSource::kMeasured;
    } else {
      row.motion = have_direction ? MotionSource::kCarried : MotionSource::kNone;
    }
    const double V = std::isnan(s.visibility) ? options.visibility : s.visibility;
    const human::Posture posture = PostureAt(track, s);
    if (have_direction) {
      row.motion_direction = direction;
      row.values = human::EvaluateFactors(curves, posture, s.part, direction, V);
    } else {
      // r, g and lambda_c do not depend on the motion: evaluate with any
      // direction, then withdraw what does (Ang, f and, through Eq. 2, eta).
      row.values =
          human::EvaluateFactors(curves, posture, s.part, Eigen::Vector3d::UnitZ(), V);
      row.values.sight_angle_deg = kNaN;
      row.values.f = kNaN;
      row.values.eta = kNaN;
    }
    out.push_back(row);
  }
  return out;
}

}  // namespace vahf::data
