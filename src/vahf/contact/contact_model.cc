#include "vahf/contact/contact_model.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "vahf/core/error.h"
#include "vahf/geometry/bounding_sphere.h"

namespace vahf::contact {
namespace {

double PairFriction(double a, double b) { return a + b > 0 ? 2 * a * b / (a + b) : 0.0; }

}  // namespace

ContactModel::ContactModel(std::vector<ShellPoint> shell, double shell_bounding_radius,
                           double moving_friction, std::vector<Obstacle> obstacles,
                           const ContactParams& params)
    : shell_(std::move(shell)),
      shell_radius_(shell_bounding_radius),
      moving_friction_(moving_friction),
      obstacles_(std::move(obstacles)),
      params_(params) {
  VAHF_CHECK(shell_.size() < (std::size_t{1} << 31), "point shell too large");
  if (!shell_.empty()) BuildTree(0, shell_.size());
}

void ContactModel::BuildTree(std::size_t begin, std::size_t end) {
  const geometry::BoundingSphere bound =
      geometry::BoundPoints(shell_.begin() + begin, shell_.begin() + end,
                            [](const ShellPoint& s) { return s.position; });
  const std::size_t index = nodes_.size();
  nodes_.push_back({bound.centre, bound.radius, static_cast<std::uint32_t>(begin),
                    static_cast<std::uint32_t>(end), 0});
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

double ContactModel::Pressure(const ContactParams& p, double depth, double depth_rate) {
  if (!(depth > 0)) return 0.0;
  const double elastic = depth < p.onset_depth
                             ? p.stiffness * depth * depth / (2 * p.onset_depth)
                             : p.stiffness * (depth - 0.5 * p.onset_depth);
  return elastic * std::max(0.0, 1.0 + p.dissipation * depth_rate);
}

ContactForces ContactModel::Evaluate(const RigidMotion& m) const {
  ++counters_.evaluations;
  ContactForces out;
  for (const Obstacle& o : obstacles_) {
    // Broad phase: bounding spheres about the two frame origins.
    const double reach = o.bounding_radius + shell_radius_;
    if ((m.pose.translation() - o.pose.translation()).squaredNorm() > reach * reach) {
      ++counters_.pairs_skipped;
      continue;
    }
    const double mu = PairFriction(moving_friction_, o.friction);
    // Shell points go to the obstacle frame with one transform.
    const Eigen::Isometry3d moving_in_obstacle = o.pose.inverse() * m.pose;
    const Eigen::Matrix3d r_world_obstacle = o.pose.linear();
    for (std::size_t i = 0; i < nodes_.size();) {
      const Node& node = nodes_[i];
      const Eigen::Vector3d c_o = moving_in_obstacle * node.centre;
      const bool clear = ((c_o.array() + node.radius) <= o.field.lower().array()).any() ||
                         ((c_o.array() - node.radius) >= o.field.upper().array()).any() ||
                         o.field.At(c_o).distance > node.radius;
      if (clear) {
        ++counters_.clusters_skipped;
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
        ++counters_.point_queries;
        const Eigen::Vector3d p_o = moving_in_obstacle * s.position;
        const std::optional<Distance> d = o.field.Penetration(p_o);
        if (!d) continue;
        const double depth = -d->distance;
        if (!(depth > 0)) continue;
        const Eigen::Vector3d n = r_world_obstacle * d->normal;  // out of the obstacle
        const Eigen::Vector3d r = m.pose.linear() * s.position;  // origin to point, world
        const Eigen::Vector3d v = m.velocity + m.angular_velocity.cross(r);
        const double depth_rate = -v.dot(n);
        const double fn = Pressure(params_, depth, depth_rate) * s.area;
        if (!(fn > 0)) continue;
        const Eigen::Vector3d v_t = v - v.dot(n) * n;
        const double slip = v_t.norm();
        const Eigen::Vector3d ft =
            -mu * fn / std::max(slip, params_.friction_transition_speed) * v_t;
        out.normal_force += fn * n;
        out.friction_force += ft;
        out.torque += r.cross(fn * n + ft);
        ++out.points_in_contact;
        out.max_depth = std::max(out.max_depth, depth);
      }
    }
  }
  return out;
}

}  // namespace vahf::contact
