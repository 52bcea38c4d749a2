// The human factors of a sensor track, computed as the paper's Sec. 5.1 does
// for its real-world trials: f from the part's motion and the sight line, r
// from the farther shoulder, g from the body plane through the body centre
// and both shoulders, V from the camera, eta and lambda_c by Eqs. 2-3. The
// sensors become a human::Posture and go through human::EvaluateFactors with
// the simulation's own curves, so a lab track and a virtual trial are
// measured by one piece of code.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "vahf/data/track.h"
#include "vahf/human/factors.h"

namespace vahf::data {

struct TrackFactorOptions {
  // V where the track has no camera value (no visibility column, or an empty
  // cell). NaN, the default, leaves eta and lambda_c NaN there (f, r and g are
  // still given): Eqs. 2-3 need V, and a guessed V would pass for a
  // measurement. A value in [0, 1] is used as given.
  double visibility = std::numeric_limits<double>::quiet_NaN();
  // |P_i - P_{i-1}| at or below which the part counts as still, m. 0: only
  // identical positions; a lab sets its sensor's resolution.
  double still_distance = 0.0;
};

// Where the motion direction of f came from at a sample.
enum class MotionSource {
  kMeasured,  // P_i - P_{i-1}, as Sec. 5.1 defines it
  kCarried,   // the part was still: the last measured direction, carried on
  kNone,      // still since the track began: no direction, f and eta are NaN
};

// The factors at one sample i >= 1 of a track.
struct TrackFactors {
  double time = 0;  // s, the sample's
  int line = 0;     // the sample's line in its file
  MotionSource motion = MotionSource::kMeasured;
  // The unit motion direction f used; NaN with MotionSource::kNone.
  Eigen::Vector3d motion_direction =
      Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  // Ang, f, the shoulder distance, r, Anp, g, V, eta and lambda_c as
  // human::EvaluateFactors gives them (Anp by human::GlanceAngleDeg's
  // convention). With MotionSource::kNone, Ang, f and eta are NaN; without
  // V (see TrackFactorOptions::visibility), V, eta and lambda_c are NaN.
  human::FactorValues values;
};

// The factors at every sample i >= 1 of `track` (sample 0 has no P_{i-1}), in
// order, evaluated with `curves`: build them as the simulation does, from the
// scene's parameters and this operator's arm length and stature (r's
// breakpoints depend on them; sim::BuildTrialModel).
//
// The posture at sample i: eye = brow (P_ie), the shoulders (P_ils, P_irs),
// body centre (P_ic), and the body plane through the last three by
// human::BodyPlaneFrom. g needs only the plane's in-plane down axis; its
// normal `forward` is oriented by the shoulders' labels: forward is
// (P_irs - P_ils) x (P_ic - shoulder midpoint), which points the way a person
// with that right and left shoulder faces (not by the brow's side of the plane:
// a brow in the plane, as in vahf's own standing posture, has no side).
//
// Throws InputError naming the track's file and the sample's line when the
// brow and the part's centre coincide (no sight line), or the shoulders and
// body centre are collinear (no body plane).
std::vector<TrackFactors> FactorsFromTrack(const SensorTrack& track,
                                           const human::FactorCurves& curves,
                                           const TrackFactorOptions& options = {});

}  // namespace vahf::data
