#include "vahf/contact/revolved_contact.h"

#include <algorithm>
#include <cmath>

#include "vahf/contact/point_load.h"

namespace vahf::contact {
namespace {

// Gauss-Radau nodes and weights on [-1, 1], the node -1 fixed (Abramowitz
// and Stegun, Handbook of Mathematical Functions, 1964, 25.4.31): exact for
// polynomials of degree 6.
constexpr double kRadauNode[4] = {-1.0, -0.575318923521694, 0.181066271118531,
                                  0.822824080974592};
constexpr double kRadauWeight[4] = {0.125, 0.657688639960120, 0.776386937686344,
                                    0.440924422353536};

}  // namespace

RevolvedContact::Solid RevolvedContact::Make(const geometry::RevolvedProfile& profile,
                                             const Eigen::Isometry3d& pose,
                                             double friction, double bounding_radius) {
  return {SignedDistance(geometry::Shape(profile)), RimCircles(profile), pose, friction,
          bounding_radius};
}

RevolvedContact::RevolvedContact(Solid moving, std::vector<Solid> fixed,
                                 const PenaltyLaw& params)
    : moving_(std::move(moving)), fixed_(std::move(fixed)), params_(params) {}

template <typename Visit>
void RevolvedContact::ForEachPass(const RigidMotion& m, double margin,
                                  ContactCounters& counters, Visit visit) const {
  for (const Solid& f : fixed_) {
    // Broad phase: bounding spheres about the two frame origins.
    const double reach = f.bounding_radius + moving_.bounding_radius + margin;
    if ((m.pose.translation() - f.pose.translation()).squaredNorm() > reach * reach) {
      ++counters.pairs_skipped;
      continue;
    }
    const double mu = PairFriction(moving_.friction, f.friction);
    const Eigen::Isometry3d moving_in_fixed = f.pose.inverse() * m.pose;
    const Eigen::Isometry3d fixed_in_moving = moving_in_fixed.inverse();
    visit(Pass{moving_, f, moving_in_fixed, f.pose.linear(), fixed_in_moving, true, mu});
    visit(Pass{f, moving_, fixed_in_moving, m.pose.linear(),
               Eigen::Isometry3d::Identity(), false, mu});
  }
}

ContactForces RevolvedContact::DoEvaluate(const RigidMotion& m, ContactCounters& counters,
                                          ContactJacobian* jacobian) const {
  ++counters.evaluations;
  ContactForces out;
  ForEachPass(m, 0.0, counters,
              [&](const Pass& pass) { EvaluatePass(pass, m, counters, &out, jacobian); });
  return out;
}

bool RevolvedContact::AddContactPoints(const RigidMotion& m, double margin,
                                       ContactCounters& counters,
                                       std::vector<ContactPoint>* points) const {
  ++counters.evaluations;
  ForEachPass(m, margin, counters,
              [&](const Pass& pass) { PassPoints(pass, m, margin, counters, points); });
  return true;
}

void RevolvedContact::PassPoints(const Pass& pass, const RigidMotion& m, double margin,
                                 ContactCounters& counters,
                                 std::vector<ContactPoint>* points) const {
  const Eigen::Matrix3d& R = pass.rim_to_field.linear();
  const double sign = pass.moving_rim ? 1.0 : -1.0;
  for (const RimCircle& rim : pass.rims.rims) {
    const PlacedCircle circle{pass.rim_to_field * Eigen::Vector3d(0, 0, rim.height),
                              R.col(0), R.col(1), rim.radius};
    const NearEdges solid = NearCircle(pass.field.field, circle, margin);
    Arc arcs[kMaxArcs];
    const int n = InsideArcs(circle, solid, arcs, &counters.rim_queries,
                             &counters.edge_tests, margin);
    if (n == 0) ++counters.rims_skipped;
    const auto add = [&](double angle) {
      const Eigen::Vector3d p = circle.At(angle);
      ++counters.rim_queries;
      const Distance d = solid.At(p, &counters.edge_tests);
      ContactPoint c;
      c.r = m.pose.linear() * (pass.field_to_moving * p);
      c.normal =
          sign * (pass.field_to_world * solid.LoadNormal(p, d, params_.edge_blend));
      c.gap = d.distance;
      c.mu = pass.mu;
      points->push_back(c);
    };
    // The arcs inside the solid, for the ends of a contact's extent.
    Arc inside[kMaxArcs];
    int inside_count = -1;
    for (int k = 0; k < n; ++k) {
      const double peak = DeepestAngle(circle, solid, arcs[k], &counters.rim_queries,
                                       &counters.edge_tests);
      if (arcs[k].whole()) {
        for (int i = 0; i < kCirclePoints; ++i) add(peak + 2 * M_PI * i / kCirclePoints);
        continue;
      }
      add(peak);
      if (!(points->back().gap < 0)) continue;
      if (inside_count < 0)
        inside_count = InsideArcs(circle, solid, inside, &counters.rim_queries,
                                  &counters.edge_tests);
      for (int j = 0; j < inside_count; ++j)
        if (!inside[j].whole() && inside[j].begin >= arcs[k].begin &&
            inside[j].end <= arcs[k].end)
          add(inside[j].begin), add(inside[j].end);
    }
  }
}

void RevolvedContact::EvaluatePass(const Pass& pass, const RigidMotion& m,
                                   ContactCounters& counters, ContactForces* out,
                                   ContactJacobian* jacobian) const {
  const Eigen::Matrix3d& R = pass.rim_to_field.linear();
  for (const RimCircle& rim : pass.rims.rims) {
    const PlacedCircle circle{pass.rim_to_field * Eigen::Vector3d(0, 0, rim.height),
                              R.col(0), R.col(1), rim.radius};
    const NearEdges solid = NearCircle(pass.field.field, circle);
    Arc arcs[kMaxArcs];
    const int n =
        InsideArcs(circle, solid, arcs, &counters.rim_queries, &counters.edge_tests);
    if (n == 0) ++counters.rims_skipped;
    for (int k = 0; k < n; ++k)
      IntegrateArc(pass, circle, solid, arcs[k], m, counters, out, jacobian);
  }
}

void RevolvedContact::IntegrateArc(const Pass& pass, const PlacedCircle& circle,
                                   const NearEdges& solid, const Arc& arc,
                                   const RigidMotion& m, ContactCounters& counters,
                                   ContactForces* out, ContactJacobian* jacobian) const {
  const Eigen::Matrix3d& r_world_moving = m.pose.linear();
  const double sign = pass.moving_rim ? 1.0 : -1.0;
  // The line load at an angle over `length` of rim; its depth.
  const auto node = [&](double angle, double length) {
    const Eigen::Vector3d p = circle.At(angle);
    ++counters.rim_queries;
    const Distance d = solid.At(p, &counters.edge_tests);
    const double x = -d.distance;
    if (!(x > 0)) return x;
    const Eigen::Vector3d r = r_world_moving * (pass.field_to_moving * p);
    const PointLoad point{
        r,
        m.velocity + m.angular_velocity.cross(r),
        sign * (pass.field_to_world * solid.LoadNormal(p, d, params_.edge_blend)),
        x,
        true,
        length,
        pass.mu,
        pass.moving_rim ? PointFrame::kMoving : PointFrame::kFixed};
    if (AddPointLoad(params_, point, m.angular_velocity, out, jacobian))
      ++out->rim_points_in_contact;
    return x;
  };
  // The deepest point is a node, so that the barrier there is felt in full.
  const double peak =
      DeepestAngle(circle, solid, arc, &counters.rim_queries, &counters.edge_tests);
  double deepest;
  if (arc.whole()) {  // the trapezoidal rule from the deepest point
    const double length = circle.radius * 2 * M_PI / kCircleNodes;
    deepest = node(peak, length);
    for (int i = 1; i < kCircleNodes; ++i)
      deepest = std::max(deepest, node(peak + 2 * M_PI * i / kCircleNodes, length));
  } else {  // Gauss-Radau on each side of the deepest point
    const double left = 0.5 * (peak - arc.begin), right = 0.5 * (arc.end - peak);
    deepest = node(peak, circle.radius * kRadauWeight[0] * (left + right));
    for (int i = 1; i < 4; ++i) {
      const double x = 1.0 + kRadauNode[i];
      deepest = std::max(deepest,
                         node(peak - x * left, circle.radius * kRadauWeight[i] * left));
      deepest = std::max(deepest,
                         node(peak + x * right, circle.radius * kRadauWeight[i] * right));
    }
  }
  out->max_depth = std::max(out->max_depth, deepest);
}

}  // namespace vahf::contact
