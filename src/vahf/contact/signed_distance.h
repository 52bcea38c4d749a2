// Exact signed distance from a point to a static part (docs/design.md decision 7):
// negative inside, with the outward unit normal at the nearest surface point.
//
// For a solid of revolution the nearest surface point of a point P lies in P's
// own meridian half-plane, so the 3-D distance is the 2-D distance from
// (r, z) = (|P_xy|, P_z) to the profile polygon's surface edges (edges lying on
// the axis r = 0 are interior, not surface, and are skipped).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "vahf/contact/sector_bound.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {

struct Distance {
  double distance;         // m, negative inside the solid
  Eigen::Vector3d normal;  // outward unit normal at the nearest surface point
};

class SignedDistance {
 public:
  explicit SignedDistance(const geometry::Shape& shape);

  // Distance from p, in the shape's frame; `edges`, when given, gains the
  // profile edges it examined (as Penetration's).
  Distance At(const Eigen::Vector3d& p, std::uint64_t* edges = nullptr) const;
  // At(p).distance > radius, the same answer to the bit, without the normal
  // and, for a solid of revolution, without the remaining edges once one is
  // within radius: the broad phase's test (a sphere of that radius about p
  // holds no point of the solid).
  bool FartherThan(const Eigen::Vector3d& p, double radius) const;
  // The contact query: At(p) when p is strictly inside the solid, nothing
  // otherwise. One inside test and, only for points inside, one distance pass.
  // `edges`, when given, gains the number of profile edges the two examined:
  // the query's work, which grows with the profile's vertices (a trial's work
  // budget counts it, simulation/max_contact_tests).
  std::optional<Distance> Penetration(const Eigen::Vector3d& p,
                                      std::uint64_t* edges = nullptr) const;
  // True when no point p with (|p_xy|, p_z) in the box lies inside the solid
  // (a solid of revolution; a box answers false, it cannot tell): no surface
  // edge of the profile meets the closed box, and the box's centre is outside
  // the profile. The broad phase's test for parts turning about a common axis
  // (sector_bound.h).
  bool MeridianBoxClear(const MeridianBox& box) const;
  // The least distance in the meridian half-plane from the box to a corner
  // of the profile (a vertex off the axis where the surface turns): infinity
  // when there is none, 0 when the box holds one, and for a box shape. Away
  // from corners the distance along a path has the curvature of the path's
  // own bend; near one it does not: on the side where the corner point is
  // the nearest (outside a convex corner, inside a concave one) it adds
  // s^2 / d for a path at speed s, d from the corner, and on the other two
  // faces meet in a kink. rim_arcs.cc bounds the distance's bend with it.
  double CornerDistance(const MeridianBox& box) const;

  // Axis-aligned bounds of the solid in its frame, m.
  const Eigen::Vector3d& lower() const { return lower_; }
  const Eigen::Vector3d& upper() const { return upper_; }

 private:
  // What the queries need of an edge beyond its ends is computed once here,
  // with the operations they used to repeat for every point: the same bits.
  struct Edge {
    Eigen::Vector2d a;        // (r, z) start
    Eigen::Vector2d ab;       // end minus start
    double ab2;               // ab.squaredNorm()
    Eigen::Vector2d outward;  // unit outward normal of the edge in (r, z)
    Eigen::Vector2d lo, hi;   // its bounding box in (r, z)
  };
  // A surface edge as the crossing number uses it: the ray at height z crosses
  // it at r = a_r + (z - a_z) / dz * dr.
  struct Crossing {
    double a_r, a_z, dz, dr;
  };
  // Declared inline so that they are compiled into Penetration and At: a call
  // and the copy of its result cost about 5 % of the queries' time.
  inline Distance OfRevolution(const Eigen::Vector3d& p, double r, bool inside) const;
  Distance OfBox(const Eigen::Vector3d& p) const;
  inline bool InsidePolygon(double r, double z, std::uint64_t* edges = nullptr) const;
  bool InBounds(const Eigen::Vector3d& p) const;

  bool is_box_ = false;
  Eigen::Vector3d half_;                  // box half extents
  std::vector<Edge> surface_;             // edges not on the axis, counter-clockwise
  std::vector<Eigen::Vector2d> corners_;  // (r, z) of CornerDistance's corners
  // The distinct heights of the surface edges' ends, ascending. Every height of
  // slab k = [slab_z_[k], slab_z_[k + 1]) is spanned by the same edges:
  // crossings_[slab_begin_[k]] up to crossings_[slab_begin_[k + 1]].
  std::vector<double> slab_z_;
  std::vector<std::size_t> slab_begin_;
  std::vector<Crossing> crossings_;
  Eigen::Vector3d lower_, upper_;
};

}  // namespace vahf::contact
