// The bounding sphere used by the broad phases (contact's point-shell tree,
// visibility's occluder culling): centred on the points' axis-aligned bounding
// box, with the radius to the farthest point. Not the minimal sphere, but
// cheap, deterministic (a fixed order of operations) and at most sqrt(3)/2 of
// the box diagonal.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <iterator>

namespace vahf::geometry {

struct BoundingSphere {
  Eigen::Vector3d lo, hi;  // the axis-aligned bounding box
  Eigen::Vector3d centre;  // its centre
  double radius = 0.0;     // to the farthest point
};

// The sphere about the points position(*it) for it in [first, last), which
// must not be empty.
template <class It, class Position>
BoundingSphere BoundPoints(It first, It last, Position position) {
  BoundingSphere s;
  s.lo = s.hi = position(*first);
  for (It it = first; it != last; ++it) {
    s.lo = s.lo.cwiseMin(position(*it));
    s.hi = s.hi.cwiseMax(position(*it));
  }
  s.centre = 0.5 * (s.lo + s.hi);
  for (It it = first; it != last; ++it)
    s.radius = std::max(s.radius, (position(*it) - s.centre).norm());
  return s;
}

}  // namespace vahf::geometry
