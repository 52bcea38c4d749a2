// How a trial obtains the visibility V of Eq. 1.
#pragma once

#include <string>

namespace vahf::visibility {

// Largest N of the ray grid: N^2 = 1 048 576 rays a decision, two orders
// above the shipped scenes' 128^2, so that one decision's work stays bounded.
inline constexpr int kMaxGrid = 1024;

struct VisibilityParams {
  // "raycast": V by casting a grid of rays from the operator's eye (Eq. 1);
  // "constant": V = `value` throughout (no tessellation, no rays);
  // "off": the visual factor is switched off, V = 1.
  std::string mode = "raycast";
  double value = 1.0;                    // V when mode is "constant"
  int grid = 128;                        // N of the N x N ray grid
  double tessellation_tolerance = 1e-4;  // chord error of part meshes, m
};

}  // namespace vahf::visibility
