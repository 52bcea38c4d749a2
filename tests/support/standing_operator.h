// A sensor track's sample of an operator who stands still, facing +x, the
// head leaning over the left shoulder towards the part (tests only; the
// geometry whose factors tests/data/track_factors_test.cc works out by hand):
//   brow E = (-0.4, 0, 0.4)
//   left shoulder L = (-0.5, 0, 0.2), right shoulder R = (-0.5, -0.4, 0.2)
//   body centre C = (-0.5, -0.2, -0.2), 0.4 m below the shoulders' midpoint.
// Body plane x = -0.5; its down axis is -z; forward, (R - L) x (C - mid) =
// (0, -0.4, 0) x (0, 0, -0.4) = (0.16, 0, 0), is +x.
#pragma once

#include <Eigen/Core>

#include "vahf/data/track.h"

namespace vahf::testing {

inline data::TrackSample StandingSample(int line, double time,
                                        const Eigen::Vector3d& part, double V) {
  data::TrackSample s;
  s.time = time;
  s.part = part;
  s.brow = Eigen::Vector3d(-0.4, 0, 0.4);
  s.left_shoulder = Eigen::Vector3d(-0.5, 0, 0.2);
  s.right_shoulder = Eigen::Vector3d(-0.5, -0.4, 0.2);
  s.body = Eigen::Vector3d(-0.5, -0.2, -0.2);
  s.visibility = V;
  s.line = line;
  return s;
}

}  // namespace vahf::testing
