// Exact signed distance from a point to a static part (docs/design.md decision 7):
// negative inside, with the outward unit normal at the nearest surface point.
//
// For a solid of revolution the nearest surface point of a point P lies in P's
// own meridian half-plane, so the 3-D distance is the 2-D distance from
// (r, z) = (|P_xy|, P_z) to the profile polygon's surface edges (edges lying on
// the axis r = 0 are interior, not surface, and are skipped).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "vahf/contact/sector_bound.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {

struct Distance {
  double distance;         // m, negative inside the solid
  Eigen::Vector3d normal;  // outward unit normal at the nearest surface point
};

// A surface edge of a profile, with what the queries need of it beyond its
// ends computed once.
struct ProfileEdge {
  Eigen::Vector2d a;        // (r, z) start
  Eigen::Vector2d ab;       // end minus start
  double ab2;               // ab.squaredNorm()
  Eigen::Vector2d outward;  // unit outward normal of the edge in (r, z)
  Eigen::Vector2d lo, hi;   // its bounding box in (r, z)
  // The sums of its outward normal and its neighbour's at its start and end
  // (the neighbour may lie on the axis): the side of a point whose nearest
  // surface point is that end is the sign of (q - end) . sum (J. A.
  // Baerentzen and H. Aanaes, Signed distance computation using the angle
  // weighted pseudonormal, IEEE TVCG 11(3), 2005; in the plane both edges
  // weigh alike).
  Eigen::Vector2d start_side, end_side;
};

class SignedDistance;

// What a solid of revolution looks like from a box of its meridian
// half-plane (SignedDistance::Near): whether the box is clear of it, the
// distance from the box to its nearest corner, and the profile edges that can
// be nearest to a point of the box. At(p) for p in the box is
// SignedDistance::At(p) from those edges alone, the sign from the nearest
// point's side (ProfileEdge::start_side) rather than a crossing count: the
// same distance to the bit, the same sign except within rounding of the
// surface, at a fraction of the work where a rim's trace meets one face.
class NearEdges {
 public:
  bool clear() const { return clear_; }
  double corner_distance() const { return corner_; }
  const MeridianBox& box() const { return box_; }
  // The distance from p, whose (|p_xy|, p_z) must lie in the box; `edges`, when
  // given, gains the edges examined, and `meridian` is set to (|p_xy|, p_z).
  Distance At(const Eigen::Vector3d& p, std::uint64_t* edges = nullptr,
              Eigen::Vector2d* meridian = nullptr) const;
  // The direction of a contact load at p inside the solid, d = At(p): d's
  // normal, blended across the solid's medial axis (SignedDistance::
  // LoadNormal).
  Eigen::Vector3d LoadNormal(const Eigen::Vector3d& p, const Distance& d,
                             double band) const;
  // The edges kept, in the profile's order; -1: all of them (not listed).
  int count() const { return count_; }
  const ProfileEdge& edge(int k) const { return *edges_[k]; }

  static constexpr int kMaxEdges = 8;

 private:
  friend class SignedDistance;
  const SignedDistance* solid_ = nullptr;
  MeridianBox box_{};
  bool clear_ = false;
  double corner_ = 0;
  int count_ = -1;  // the edges below; -1: all of them, through solid_->At
  const ProfileEdge* edges_[kMaxEdges] = {};
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
  // The direction of a contact load at p strictly inside the solid, d =
  // At(p). Inside a corner where two faces meet at an angle (a sharp edge of
  // the part), the nearest face changes across the corner's medial axis and
  // d's normal jumps there, by the corner's turn: a load along it would jump
  // with position, which no integrator steps across. So each surface edge
  // whose distance d_e is within `band` of the depth -d.distance adds its
  // direction (from p to its nearest point) with the weight s(t), t = 1 -
  // (d_e + d.distance) / band, s(t) = 3 t^2 - 2 t^3 (C1, 1 for the nearest):
  // equal halves on the axis, the nearest face's alone `band` of depth
  // difference from it. The depth stays exact. A box, a point outside, or
  // band <= 0: d's normal.
  Eigen::Vector3d LoadNormal(const Eigen::Vector3d& p, const Distance& d,
                             double band) const;
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
  // The solid as seen from a box (NearEdges): an edge is kept when its least
  // distance to the box is at most the least, over edges, of the greatest
  // distance from the box to an edge (so it holds every point's nearest);
  // more than NearEdges::kMaxEdges, or a box shape: all of them.
  NearEdges Near(const MeridianBox& box) const;

  // Axis-aligned bounds of the solid in its frame, m.
  const Eigen::Vector3d& lower() const { return lower_; }
  const Eigen::Vector3d& upper() const { return upper_; }

 private:
  // What the queries need of an edge beyond its ends is computed once,
  // with the operations they used to repeat for every point: the same bits.
  using Edge = ProfileEdge;
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

namespace detail {

// The nearest point of a profile's surface edges to q = (r, z) in the
// meridian half-plane: the least squared distance, the point, and the edge
// and parameter t in [0, 1] along it (the first edge of a tie).
struct Nearest {
  double d2 = std::numeric_limits<double>::infinity();
  Eigen::Vector2d point;
  const ProfileEdge* edge = nullptr;
  double t = 0;
  void Consider(const Eigen::Vector2d& q, const ProfileEdge& e) {
    const double s = std::clamp((q - e.a).dot(e.ab) / e.ab2, 0.0, 1.0);
    const Eigen::Vector2d c = e.a + s * e.ab;
    const double d = (q - c).squaredNorm();
    if (d < d2) d2 = d, point = c, edge = &e, t = s;
  }
};

// The 3-D distance and normal of p, r = |p_xy|, from its nearest surface
// point in the meridian half-plane.
inline Distance FromNearest(const Eigen::Vector3d& p, double r, const Eigen::Vector2d& q,
                            const Nearest& near, bool inside) {
  const double d = std::sqrt(near.d2);
  Eigen::Vector2d n2 = near.edge ? near.edge->outward : Eigen::Vector2d(1, 0);
  if (d > 1e-12) n2 = (inside ? near.point - q : q - near.point) / d;
  const Eigen::Vector2d radial =
      r > 0 ? Eigen::Vector2d(p.x() / r, p.y() / r) : Eigen::Vector2d(1, 0);
  return {inside ? -d : d,
          Eigen::Vector3d(n2.x() * radial.x(), n2.x() * radial.y(), n2.y())};
}

// LoadNormal over the edges [first, last) (pointers to edges, or edges):
// each edge's direction from q = (|p_xy|, p_z) to its nearest point, weighed
// by s(t), summed, normalized and turned into p's meridian half-plane; d's
// normal when no edge weighs.
template <typename It, typename Deref>
Eigen::Vector3d BlendedNormal(const Eigen::Vector3d& p, const Distance& d, double band,
                              It first, It last, Deref edge_of) {
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
  const Eigen::Vector2d q(r, p.z());
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (It it = first; it != last; ++it) {
    const ProfileEdge& e = edge_of(*it);
    const double s = std::clamp((q - e.a).dot(e.ab) / e.ab2, 0.0, 1.0);
    const Eigen::Vector2d to = e.a + s * e.ab - q;
    const double de = to.norm();
    const double t = std::min(1.0, 1.0 - (de + d.distance) / band);
    if (!(t > 0) || !(de > 1e-12)) continue;
    sum += t * t * (3 - 2 * t) / de * to;
  }
  const double norm = sum.norm();
  if (!(norm > 0)) return d.normal;
  const Eigen::Vector2d n2 = sum / norm;
  const Eigen::Vector2d radial =
      r > 0 ? Eigen::Vector2d(p.x() / r, p.y() / r) : Eigen::Vector2d(1, 0);
  return Eigen::Vector3d(n2.x() * radial.x(), n2.x() * radial.y(), n2.y());
}

}  // namespace detail

inline Eigen::Vector3d NearEdges::LoadNormal(const Eigen::Vector3d& p, const Distance& d,
                                             double band) const {
  if (count_ < 0) return solid_->LoadNormal(p, d, band);
  if (!(band > 0) || !(d.distance < 0)) return d.normal;
  return detail::BlendedNormal(
      p, d, band, edges_, edges_ + count_,
      [](const ProfileEdge* e) -> const ProfileEdge& { return *e; });
}

// Defined here so that a rim's queries (rim_arcs.cc) compile it in.
inline Distance NearEdges::At(const Eigen::Vector3d& p, std::uint64_t* edges,
                              Eigen::Vector2d* meridian) const {
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
  const Eigen::Vector2d q(r, p.z());
  if (meridian) *meridian = q;
  if (count_ < 0) return solid_->At(p, edges);
  detail::Nearest near;
  near.point = q;
  for (int k = 0; k < count_; ++k) near.Consider(q, *edges_[k]);
  if (!near.edge) return solid_->At(p, edges);  // not a number
  if (edges) *edges += static_cast<std::uint64_t>(count_);
  // The nearest point's side: an edge's interior by its normal, an end by
  // the sum of the normals meeting there.
  const ProfileEdge& e = *near.edge;
  const Eigen::Vector2d& side = near.t <= 0.0   ? e.start_side
                                : near.t >= 1.0 ? e.end_side
                                                : e.outward;
  return detail::FromNearest(p, r, q, near, (q - near.point).dot(side) < 0);
}

}  // namespace vahf::contact
