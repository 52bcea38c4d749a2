#include "vahf/contact/signed_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vahf::contact {

SignedDistance::SignedDistance(const geometry::Shape& shape) {
  if (const auto* box = std::get_if<geometry::Box>(&shape)) {
    is_box_ = true;
    half_ = 0.5 * box->size;
    lower_ = -half_;
    upper_ = half_;
    return;
  }
  const auto& v = std::get<geometry::RevolvedProfile>(shape).vertices;
  double r_max = 0, z_min = std::numeric_limits<double>::infinity(), z_max = -z_min;
  for (const auto& q : v) {
    r_max = std::max(r_max, q.r);
    z_min = std::min(z_min, q.z);
    z_max = std::max(z_max, q.z);
  }
  const std::size_t n = v.size();
  const auto vertex = [&](std::size_t k) {
    return Eigen::Vector2d(v[k % n].r, v[k % n].z);
  };
  // The outward normal of the polygon's edge k (from vertex k to k + 1): the
  // polygon is counter-clockwise, so it is the edge's direction turned
  // clockwise. Zero for an edge of no length.
  const auto outward = [&](std::size_t k) {
    const Eigen::Vector2d ab = vertex(k + 1) - vertex(k);
    if (ab.squaredNorm() == 0.0) return Eigen::Vector2d(0, 0);
    const Eigen::Vector2d d = ab.normalized();
    return Eigen::Vector2d(d.y(), -d.x());
  };
  // The nearest edge of some length before (step n - 1) or after (step 1) k.
  const auto neighbour = [&](std::size_t k, std::size_t step) {
    for (std::size_t i = 1; i < n; ++i) {
      const Eigen::Vector2d o = outward(k + i * step);
      if (o.squaredNorm() > 0) return o;
    }
    return Eigen::Vector2d(0, 0);
  };
  std::vector<double> end_z;  // the surface edges' end heights, in surface_'s order
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d a = vertex(k), b = vertex(k + 1);
    if (a.x() == 0.0 && b.x() == 0.0) continue;  // on the axis: interior in 3-D
    const Eigen::Vector2d ab = b - a;
    const Eigen::Vector2d out = outward(k);
    surface_.push_back({a, ab, ab.squaredNorm(), out, a.cwiseMin(b), a.cwiseMax(b),
                        out + neighbour(k, n - 1), out + neighbour(k, 1)});
    end_z.push_back(b.y());
    slab_z_.push_back(a.y());
    slab_z_.push_back(b.y());
  }
  // The corners: vertices off the axis where the surface turns.
  for (std::size_t k = 0; k < n; ++k) {
    const geometry::ProfilePoint a = v[(k + n - 1) % n], b = v[k], c = v[(k + 1) % n];
    if (!(b.r > 0)) continue;
    if ((b.r - a.r) * (c.z - b.z) - (b.z - a.z) * (c.r - b.r) != 0)
      corners_.emplace_back(b.r, b.z);
  }
  std::sort(slab_z_.begin(), slab_z_.end());
  slab_z_.erase(std::unique(slab_z_.begin(), slab_z_.end()), slab_z_.end());
  // No edge end lies inside a slab, so an edge spans every height of a slab
  // exactly when it spans the slab's lowest.
  for (std::size_t k = 0; k + 1 < slab_z_.size(); ++k) {
    slab_begin_.push_back(crossings_.size());
    for (std::size_t j = 0; j < surface_.size(); ++j) {
      const Edge& e = surface_[j];
      if ((e.a.y() > slab_z_[k]) != (end_z[j] > slab_z_[k]))
        crossings_.push_back({e.a.x(), e.a.y(), e.ab.y(), e.ab.x()});
    }
  }
  slab_begin_.push_back(crossings_.size());
  lower_ = {-r_max, -r_max, z_min};
  upper_ = {r_max, r_max, z_max};
}

bool SignedDistance::InsidePolygon(double r, double z, std::uint64_t* edges) const {
  // Crossing number along +r. Edges on the axis (r = 0) are never crossed by a
  // ray from r >= 0, so the surface edges suffice, and of those only the ones
  // spanning z: the edges of z's slab. Below the lowest end or at or above the
  // highest no edge spans z.
  const auto above = std::upper_bound(slab_z_.begin(), slab_z_.end(), z);
  if (above == slab_z_.begin() || above == slab_z_.end()) return false;
  const std::size_t k = static_cast<std::size_t>(above - slab_z_.begin()) - 1;
  if (edges) *edges += slab_begin_[k + 1] - slab_begin_[k];
  bool inside = false;
  for (std::size_t j = slab_begin_[k]; j < slab_begin_[k + 1]; ++j) {
    const Crossing& c = crossings_[j];
    // On an edge parallel to the axis (dr = 0) the quotient is finite (z lies
    // between the edge's ends, so it is at most 1 in magnitude), times dr it is
    // a zero, and a_r plus a zero compares as a_r: the division is skipped, the
    // answer is the same.
    const double r_cross = c.dr == 0 ? c.a_r : c.a_r + (z - c.a_z) / c.dz * c.dr;
    if (r < r_cross) inside = !inside;
  }
  return inside;
}

bool SignedDistance::InBounds(const Eigen::Vector3d& p) const {
  return (p.array() > lower_.array()).all() && (p.array() < upper_.array()).all();
}

std::optional<Distance> SignedDistance::Penetration(const Eigen::Vector3d& p,
                                                    std::uint64_t* edges) const {
  if (!InBounds(p)) return std::nullopt;
  if (is_box_) return OfBox(p);
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
  if (!InsidePolygon(r, p.z(), edges)) return std::nullopt;
  if (edges) *edges += surface_.size();
  return OfRevolution(p, r, true);
}

Distance SignedDistance::At(const Eigen::Vector3d& p, std::uint64_t* edges) const {
  if (is_box_) return OfBox(p);
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
  const bool inside = InsidePolygon(r, p.z(), edges);
  if (edges) *edges += surface_.size();
  return OfRevolution(p, r, inside);
}

bool SignedDistance::FartherThan(const Eigen::Vector3d& p, double radius) const {
  if (is_box_) return OfBox(p).distance > radius;
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
  if (!(radius >= 0)) return At(p).distance > radius;  // not a sphere's radius
  // Inside, At's distance is -sqrt(best) <= 0 <= radius.
  if (InsidePolygon(r, p.z())) return false;
  // As OfRevolution's loop. An edge with d2 clearly under radius^2 settles it:
  // the minimum is at most d2, and sqrt is monotone. The factor keeps the
  // shortcut on the safe side of the rounding of radius * radius.
  const Eigen::Vector2d q(r, p.z());
  const double settled = radius * radius * (1.0 - 1e-12);
  double best = std::numeric_limits<double>::infinity();
  for (const Edge& e : surface_) {
    const double t = std::clamp((q - e.a).dot(e.ab) / e.ab2, 0.0, 1.0);
    const Eigen::Vector2d c = e.a + t * e.ab;
    const double d2 = (q - c).squaredNorm();
    if (d2 < settled) return false;
    if (d2 < best) best = d2;
  }
  return std::sqrt(best) > radius;
}

Eigen::Vector3d SignedDistance::LoadNormal(const Eigen::Vector3d& p, const Distance& d,
                                           double band) const {
  if (is_box_ || !(band > 0) || !(d.distance < 0)) return d.normal;
  return detail::BlendedNormal(p, d, band, surface_.begin(), surface_.end(),
                               [](const Edge& e) -> const ProfileEdge& { return e; });
}

namespace {

// Whether the segment a + t ab, t in [0, 1], meets the closed box [lo, hi]
// (Liang and Barsky's clipping, Computer Vision, Graphics, and Image
// Processing 9(3), 1984).
bool SegmentMeetsBox(const Eigen::Vector2d& a, const Eigen::Vector2d& ab,
                     const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    const double below = lo[axis] - a[axis], above = hi[axis] - a[axis];
    if (ab[axis] == 0.0) {
      if (below > 0.0 || above < 0.0) return false;  // parallel, outside the slab
      continue;
    }
    double ta = below / ab[axis], tb = above / ab[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

bool SignedDistance::MeridianBoxClear(const MeridianBox& box) const {
  if (is_box_) return false;
  const Eigen::Vector2d lo(std::max(0.0, box.r_min), box.z_min), hi(box.r_max, box.z_max);
  if (!(lo.x() <= hi.x() && lo.y() <= hi.y())) return false;  // not a box (NaN)
  if (lo.x() >= upper_.x() || hi.y() <= lower_.z() || lo.y() >= upper_.z()) return true;
  for (const Edge& e : surface_)
    if ((e.lo.array() <= hi.array()).all() && (e.hi.array() >= lo.array()).all() &&
        SegmentMeetsBox(e.a, e.ab, lo, hi))
      return false;
  // No surface edge meets the box, and in r > 0 the profile's boundary is all
  // surface edges: the box lies wholly inside the solid or wholly outside it.
  return !InsidePolygon(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()));
}

double SignedDistance::CornerDistance(const MeridianBox& box) const {
  if (is_box_) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& c : corners_) {
    const double dr = std::max({box.r_min - c.x(), c.x() - box.r_max, 0.0});
    const double dz = std::max({box.z_min - c.y(), c.y() - box.z_max, 0.0});
    best = std::min(best, std::hypot(dr, dz));
  }
  return best;
}

namespace {

// The squared distance from q to the segment e.
double SegmentDistance2(const Eigen::Vector2d& q, const ProfileEdge& e) {
  detail::Nearest near;
  near.Consider(q, e);
  return near.d2;
}

// The squared distance from q to the box [lo, hi].
double BoxDistance2(const Eigen::Vector2d& q, const Eigen::Vector2d& lo,
                    const Eigen::Vector2d& hi) {
  return (lo - q).cwiseMax(q - hi).cwiseMax(0.0).squaredNorm();
}

}  // namespace

Distance SignedDistance::OfRevolution(const Eigen::Vector3d& p, double r,
                                      bool inside) const {
  const Eigen::Vector2d q(r, p.z());
  detail::Nearest near;
  near.point = q;
  for (const Edge& e : surface_) near.Consider(q, e);
  return detail::FromNearest(p, r, q, near, inside);
}

NearEdges SignedDistance::Near(const MeridianBox& box) const {
  NearEdges out;
  out.solid_ = this;
  out.box_ = box;
  if (is_box_) return out;
  out.clear_ = MeridianBoxClear(box);
  if (out.clear_) return out;
  out.corner_ = CornerDistance(box);
  const Eigen::Vector2d lo(std::max(0.0, box.r_min), box.z_min), hi(box.r_max, box.z_max);
  const Eigen::Vector2d corner[4] = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  // The greatest squared distance from the box to an edge is at one of the
  // box's corners (the distance to a segment is convex); the least of those
  // bounds every point's nearest edge.
  double bound = std::numeric_limits<double>::infinity();
  for (const Edge& e : surface_) {
    double far = 0;
    for (const Eigen::Vector2d& c : corner) far = std::max(far, SegmentDistance2(c, e));
    bound = std::min(bound, far);
  }
  // Widened far above the rounding of the sums, so that rounding can only
  // keep an edge more.
  bound = bound * (1 + 1e-6) + 1e-24;
  int count = 0;
  for (const Edge& e : surface_) {
    // The least distance from the box to a segment it does not meet is at a
    // vertex of one of them (both convex).
    double least = 0;
    if (!SegmentMeetsBox(e.a, e.ab, lo, hi)) {
      least = std::min(BoxDistance2(e.a, lo, hi), BoxDistance2(e.a + e.ab, lo, hi));
      for (const Eigen::Vector2d& c : corner)
        least = std::min(least, SegmentDistance2(c, e));
    }
    if (least > bound) continue;
    if (count == NearEdges::kMaxEdges) return out;  // too many: all of them
    out.edges_[count++] = &e;
  }
  if (count > 0) out.count_ = count;
  return out;
}

Distance SignedDistance::OfBox(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d q = p.cwiseAbs() - half_;
  if ((q.array() > 0).any()) {  // outside: distance to the nearest box point
    const Eigen::Vector3d outside = q.cwiseMax(0.0);
    Eigen::Vector3d n = outside.cwiseProduct(p.cwiseSign());
    const double d = n.norm();
    return {d, n / d};
  }
  int axis;  // inside: the nearest face
  const double d = q.maxCoeff(&axis);
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  n[axis] = p[axis] >= 0 ? 1.0 : -1.0;
  return {d, n};
}

}  // namespace vahf::contact
