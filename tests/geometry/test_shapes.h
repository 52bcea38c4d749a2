// Shapes the geometry and visibility tests build through geometry::Shape.
#pragma once

#include <cmath>
#include <vector>

#include "vahf/geometry/shape.h"

namespace vahf::geometry::testing {

// A solid of revolution from an open list of profile points (closed here).
inline Shape Revolved(std::vector<ProfilePoint> points) {
  points.push_back(points.front());
  return MakeRevolvedProfile(points);
}

// A ball of radius `radius` about the part origin: a semicircle polygon of
// `arcs` edges from the south pole to the north pole, closed along the axis.
inline Shape Ball(double radius, int arcs) {
  std::vector<ProfilePoint> p;
  for (int i = 0; i <= arcs; ++i) {
    const double phi = M_PI * i / arcs;
    p.push_back(
        {i == 0 || i == arcs ? 0.0 : radius * std::sin(phi), -radius * std::cos(phi)});
  }
  return Revolved(p);
}

}  // namespace vahf::geometry::testing
