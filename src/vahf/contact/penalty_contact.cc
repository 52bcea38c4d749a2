#include "vahf/contact/penalty_contact.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "vahf/core/error.h"
#include "vahf/geometry/bounding_sphere.h"

namespace vahf::contact {
namespace {

// True when no point of a cluster (its sphere: centre c in the field's frame
// and radius; its sector bound in its own frame, carried to the field's frame
// by `to_field`) can be inside the solid: the sphere lies outside the solid's
// bounds, or the sector bound misses a solid of revolution's profile, or the
// sphere's centre is farther from the solid than its radius (a signed
// distance is 1-Lipschitz). Cheapest first; the distance test is left out
// when the meridian box is narrower than the sphere (the parts turn about
// nearly one axis), where it would not cull what the box did not.
bool ClusterClear(const SignedDistance& field, const Eigen::Vector3d& c, double radius,
                  const SectorBound& sector, const MeridianMap& to_field) {
  if (((c.array() + radius) <= field.lower().array()).any() ||
      ((c.array() - radius) >= field.upper().array()).any())
    return true;
  const MeridianBox box = to_field(sector);
  if (field.MeridianBoxClear(box)) return true;
  if (box.r_max - box.r_min < radius) return false;
  return field.FartherThan(c, radius);
}

template <class It, class Position>
SectorBound SectorOf(It first, It last, Position position) {
  std::vector<Eigen::Vector3d> points;
  for (It it = first; it != last; ++it) points.push_back(position(*it));
  return BoundSector(points);
}

// A point of the moving part inside an obstacle: its depth, the unit normal
// out of the obstacle, its offset from the moving origin and its material
// velocity (world).
struct Hit {
  double depth;
  Eigen::Vector3d n, r, v;
};

// The moving-part point p (part frame) against obstacle o's exact field.
std::optional<Hit> MovingPointInside(const Obstacle& o,
                                     const Eigen::Isometry3d& moving_in_obstacle,
                                     const RigidMotion& m, const Eigen::Vector3d& p,
                                     ContactCounters& counters) {
  const std::optional<Distance> d =
      o.field.Penetration(moving_in_obstacle * p, &counters.edge_tests);
  if (!d || !(-d->distance > 0)) return std::nullopt;
  const Eigen::Vector3d r = m.pose.linear() * p;  // origin to point, world
  return Hit{-d->distance, o.pose.linear() * d->normal, r,
             m.velocity + m.angular_velocity.cross(r)};
}

}  // namespace

PenaltyContact::PenaltyContact(std::vector<ShellPoint> shell, SignedDistance moving_field,
                               double moving_bounding_radius, double moving_friction,
                               std::vector<Obstacle> obstacles, const PenaltyLaw& params,
                               std::vector<RimPoint> moving_rim)
    : shell_(std::move(shell)),
      moving_field_(std::move(moving_field)),
      shell_radius_(moving_bounding_radius),
      moving_friction_(moving_friction),
      obstacles_(std::move(obstacles)),
      params_(params) {
  VAHF_CHECK(shell_.size() < (std::size_t{1} << 31), "point shell too large");
  if (!shell_.empty()) BuildTree(0, shell_.size());
  rim_sets_.reserve(obstacles_.size());
  for (const Obstacle& o : obstacles_) rim_sets_.push_back(BuildRimSet(o.rim));
  moving_rim_ = std::move(moving_rim);
  moving_rim_set_ = BuildRimSet(moving_rim_);
}

PenaltyContact::RimSet PenaltyContact::BuildRimSet(const std::vector<RimPoint>& rim) {
  VAHF_CHECK(rim.size() < (std::size_t{1} << 31), "rim too large");
  RimSet set;
  if (rim.empty()) return set;
  const auto position = [](const RimPoint& q) { return q.position; };
  const geometry::BoundingSphere all =
      geometry::BoundPoints(rim.begin(), rim.end(), position);
  set.centre = all.centre;
  set.radius = all.radius;
  for (std::size_t begin = 0; begin < rim.size(); begin += kRimBlockSize) {
    const std::size_t end = std::min(rim.size(), begin + kRimBlockSize);
    const geometry::BoundingSphere b =
        geometry::BoundPoints(rim.begin() + begin, rim.begin() + end, position);
    set.blocks.push_back(
        {b.centre, b.radius, SectorOf(rim.begin() + begin, rim.begin() + end, position),
         static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)});
  }
  return set;
}

void PenaltyContact::BuildTree(std::size_t begin, std::size_t end) {
  const auto position = [](const ShellPoint& s) { return s.position; };
  const geometry::BoundingSphere bound =
      geometry::BoundPoints(shell_.begin() + begin, shell_.begin() + end, position);
  const std::size_t index = nodes_.size();
  nodes_.push_back({bound.centre, bound.radius,
                    SectorOf(shell_.begin() + begin, shell_.begin() + end, position),
                    static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end),
                    0});
  if (end - begin > kLeafSize) {
    int axis;
    (bound.hi - bound.lo).maxCoeff(&axis);
    const std::size_t mid = begin + (end - begin) / 2;
    // A total order (coordinate, then original position) makes the split,
    // and so the summation order, independent of the library's sort.
    std::stable_sort(shell_.begin() + begin, shell_.begin() + end,
                     [axis](const ShellPoint& a, const ShellPoint& b) {
                       return a.position[axis] < b.position[axis];
                     });
    BuildTree(begin, mid);
    BuildTree(mid, end);
  }
  nodes_[index].escape = static_cast<std::uint32_t>(nodes_.size());
}

ContactForces PenaltyContact::DoEvaluate(const RigidMotion& m, ContactCounters& counters,
                                         ContactJacobian* jacobian) const {
  ++counters.evaluations;
  ContactForces out;
  for (std::size_t index = 0; index < obstacles_.size(); ++index) {
    const Obstacle& o = obstacles_[index];
    // Broad phase: bounding spheres about the two frame origins.
    const double reach = o.bounding_radius + shell_radius_;
    if ((m.pose.translation() - o.pose.translation()).squaredNorm() > reach * reach) {
      ++counters.pairs_skipped;
      continue;
    }
    const double mu = PairFriction(moving_friction_, o.friction);
    // Shell points go to the obstacle frame with one transform.
    const Eigen::Isometry3d moving_in_obstacle = o.pose.inverse() * m.pose;
    const MeridianMap to_obstacle(moving_in_obstacle);
    for (std::size_t i = 0; i < nodes_.size();) {
      const Node& node = nodes_[i];
      const Eigen::Vector3d c_o = moving_in_obstacle * node.centre;
      if (ClusterClear(o.field, c_o, node.radius, node.sector, to_obstacle)) {
        ++counters.clusters_skipped;
        i = node.escape;
        continue;
      }
      if (node.end - node.begin > kLeafSize) {  // descend
        ++i;
        continue;
      }
      i = node.escape;
      for (std::size_t k = node.begin; k < node.end; ++k) {
        const ShellPoint& s = shell_[k];
        ++counters.point_queries;
        const std::optional<Hit> h =
            MovingPointInside(o, moving_in_obstacle, m, s.position, counters);
        if (!h || !AddPointLoad(params_,
                                {h->r, h->v, h->n, h->depth, false, s.area, mu,
                                 PointFrame::kMoving},
                                m.angular_velocity, &out, jacobian))
          continue;
        ++out.points_in_contact;
        out.max_depth = std::max(out.max_depth, h->depth);
      }
    }
    EvaluateMovingRims(index, m, moving_in_obstacle, to_obstacle, mu, counters, &out,
                       jacobian);
    EvaluateRims(index, m, mu, counters, &out, jacobian);
  }
  return out;
}

void PenaltyContact::EvaluateMovingRims(std::size_t index, const RigidMotion& m,
                                        const Eigen::Isometry3d& moving_in_obstacle,
                                        const MeridianMap& to_obstacle, double mu,
                                        ContactCounters& counters, ContactForces* out,
                                        ContactJacobian* jacobian) const {
  const Obstacle& o = obstacles_[index];
  for (const RimBlock& block : moving_rim_set_.blocks) {
    const Eigen::Vector3d c_o = moving_in_obstacle * block.centre;
    if (ClusterClear(o.field, c_o, block.radius, block.sector, to_obstacle)) {
      ++counters.rim_blocks_skipped;
      continue;
    }
    for (std::size_t k = block.begin; k < block.end; ++k) {
      const RimPoint& q = moving_rim_[k];
      ++counters.rim_queries;
      const std::optional<Hit> h =
          MovingPointInside(o, moving_in_obstacle, m, q.position, counters);
      if (!h || !AddPointLoad(
                    params_,
                    {h->r, h->v, h->n, h->depth, true, q.length, mu, PointFrame::kMoving},
                    m.angular_velocity, out, jacobian))
        continue;
      ++out->rim_points_in_contact;
      out->max_depth = std::max(out->max_depth, h->depth);
    }
  }
}

void PenaltyContact::EvaluateRims(std::size_t index, const RigidMotion& m, double mu,
                                  ContactCounters& counters, ContactForces* out,
                                  ContactJacobian* jacobian) const {
  const Obstacle& o = obstacles_[index];
  const RimSet& set = rim_sets_[index];
  if (set.blocks.empty()) return;
  // Rim points go to the moving frame with one transform.
  const Eigen::Isometry3d obstacle_in_moving = m.pose.inverse() * o.pose;
  if ((obstacle_in_moving * set.centre).norm() > set.radius + shell_radius_) {
    ++counters.rims_skipped;
    return;
  }
  const Eigen::Matrix3d& r_world_moving = m.pose.linear();
  const MeridianMap to_moving(obstacle_in_moving);
  for (const RimBlock& block : set.blocks) {
    const Eigen::Vector3d c_m = obstacle_in_moving * block.centre;
    if (ClusterClear(moving_field_, c_m, block.radius, block.sector, to_moving)) {
      ++counters.rim_blocks_skipped;
      continue;
    }
    for (std::size_t k = block.begin; k < block.end; ++k) {
      const RimPoint& q = o.rim[k];
      ++counters.rim_queries;
      const Eigen::Vector3d p_m = obstacle_in_moving * q.position;
      const std::optional<Distance> d =
          moving_field_.Penetration(p_m, &counters.edge_tests);
      if (!d) continue;
      const double depth = -d->distance;
      if (!(depth > 0)) continue;
      // The rim pushes the moving part inwards, against its outward normal.
      const Eigen::Vector3d u = -(r_world_moving * d->normal);
      const Eigen::Vector3d r = r_world_moving * p_m;  // origin to point, world
      const Eigen::Vector3d v = m.velocity + m.angular_velocity.cross(r);  // its material
      if (!AddPointLoad(params_, {r, v, u, depth, true, q.length, mu, PointFrame::kFixed},
                        m.angular_velocity, out, jacobian))
        continue;
      ++out->rim_points_in_contact;
      out->max_depth = std::max(out->max_depth, depth);
    }
  }
}

}  // namespace vahf::contact
