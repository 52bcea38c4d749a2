// How a trial obtains the visibility V of Eq. 1.
#pragma once

#include <string>

namespace vahf::visibility {

struct VisibilityParams {
  // "raycast": V by casting a grid of rays from the operator's eye (Eq. 1);
  // "constant": V = `value` throughout (no tessellation, no rays);
  // "off": the visual factor is switched off, V = 1.
  std::string mode = "raycast";
  double value = 1.0;          // V when mode is "constant"
  int grid = 128;              // N of the N x N ray grid
  double tessellation_tolerance = 1e-4;  // chord error of part meshes, m
};

}  // namespace vahf::visibility
