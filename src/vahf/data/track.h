// A sensor track of a lab trial (the paper's Sec. 5.1): the positions of the
// sensors on the assembling part's centre, the operator's brow, both shoulders
// and the centre of the body over time, and optionally V from the camera. SI
// units, the scene's world frame (z up); docs/lab-data.md, "tracks".
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

namespace vahf::data {

struct TrackSample {
  double time = 0;                 // s
  Eigen::Vector3d part;            // P_i, the assembling part's centre, m
  Eigen::Vector3d brow;            // P_ie, the eyes
  Eigen::Vector3d left_shoulder;   // P_ils
  Eigen::Vector3d right_shoulder;  // P_irs
  Eigen::Vector3d body;            // P_ic, the centre of the body
  // V from the camera (Eq. 1), in [0, 1]; NaN where the track has none.
  double visibility = std::numeric_limits<double>::quiet_NaN();
  int line = 0;  // in its file, for messages
};

struct SensorTrack {
  std::string file;         // as the manifest resolves it
  std::string operator_id;  // as in trials.csv
  std::string condition;
  int repetition = 0;
  std::vector<TrackSample> samples;  // time strictly increasing, at least 2
};

}  // namespace vahf::data
