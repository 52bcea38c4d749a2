// Exact signed distance from a point to a static part (docs/design.md decision 7):
// negative inside, with the outward unit normal at the nearest surface point.
//
// For a solid of revolution the nearest surface point of a point P lies in P's
// own meridian half-plane, so the 3-D distance is the 2-D distance from
// (r, z) = (|P_xy|, P_z) to the profile polygon's surface edges (edges lying on
// the axis r = 0 are interior, not surface, and are skipped).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "vahf/geometry/shape.h"

namespace vahf::contact {

struct Distance {
  double distance;         // m, negative inside the solid
  Eigen::Vector3d normal;  // outward unit normal at the nearest surface point
};

class SignedDistance {
 public:
  explicit SignedDistance(const geometry::Shape& shape);

  // Distance from p, in the shape's frame.
  Distance At(const Eigen::Vector3d& p) const;
  // The contact query: At(p) when p is strictly inside the solid, nothing
  // otherwise. One inside test and, only for points inside, one distance pass.
  std::optional<Distance> Penetration(const Eigen::Vector3d& p) const;

  // Axis-aligned bounds of the solid in its frame, m.
  const Eigen::Vector3d& lower() const { return lower_; }
  const Eigen::Vector3d& upper() const { return upper_; }

 private:
  struct Edge {
    Eigen::Vector2d a, b;     // (r, z) endpoints
    Eigen::Vector2d outward;  // unit outward normal of the edge in (r, z)
  };
  Distance OfRevolution(const Eigen::Vector3d& p, double r, bool inside) const;
  Distance OfBox(const Eigen::Vector3d& p) const;
  bool InsidePolygon(double r, double z) const;
  bool InBounds(const Eigen::Vector3d& p) const;

  bool is_box_ = false;
  Eigen::Vector3d half_;       // box half extents
  std::vector<Edge> surface_;  // edges not on the axis, counter-clockwise
  Eigen::Vector3d lower_, upper_;
};

}  // namespace vahf::contact
