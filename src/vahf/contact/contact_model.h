// The contact-model interface (docs/design.md decision 7): what a trial asks
// of the contact between its one moving part and the scene's fixed parts, at
// one motion of the moving part. A model is built once per part of a scene
// (contact_registry.h) and shared by every trial of it, on any thread: its
// Evaluate is const and writes only the caller's counters.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace vahf::contact {

// The moving part's motion: its frame in the world, and the velocity of its
// origin and its angular velocity, both in the world frame.
struct RigidMotion {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
};

struct ContactForces {
  Eigen::Vector3d normal_force = Eigen::Vector3d::Zero();    // N, world
  Eigen::Vector3d friction_force = Eigen::Vector3d::Zero();  // N, world
  // The oil film's load (squeeze_film.h), N, world: not a contact the
  // operator feels (Eq. 8 reads the normal force and friction only).
  Eigen::Vector3d film_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m about the moving origin, world
  int points_in_contact = 0;      // points of the moving part inside a fixed one
  int rim_points_in_contact = 0;  // fixed parts' rim points inside the moving part
  double max_depth = 0.0;         // m, the deepest contact
  bool in_contact() const { return points_in_contact + rim_points_in_contact > 0; }
};

// The derivative of the contact's loads with respect to the moving part's
// motion, for implicit integrators (contact_jacobian.h). Each block is 3 x 12:
// rows the world components; columns, three each, (dx, dtheta, v, w): a small
// translation of the part (world), a small rotation of it about its origin
// (world rotation vector: R -> exp([dtheta]x) R, the origin fixed), its
// velocity and its angular velocity.
struct ContactJacobian {
  using Block = Eigen::Matrix<double, 3, 12>;
  Block normal_force = Block::Zero();
  Block friction_force = Block::Zero();
  Block film_force = Block::Zero();
  Block torque = Block::Zero();  // about the moving origin
};

// Work counters: what the broad phase saved and what the narrow phase did.
struct ContactCounters {
  std::uint64_t evaluations = 0;       // calls of Evaluate
  std::uint64_t pairs_skipped = 0;     // obstacle pairs rejected by bounding spheres
  std::uint64_t point_queries = 0;     // shell points tested against an obstacle
  std::uint64_t clusters_skipped = 0;  // shell tree nodes proven clear of an obstacle
  std::uint64_t rims_skipped = 0;  // obstacles' rims wholly clear of the moving sphere
  std::uint64_t rim_queries = 0;   // rim points tested against the moving part
  std::uint64_t rim_blocks_skipped = 0;  // runs of rim points proven clear of it
  // Profile edges the point and rim queries examined (SignedDistance::
  // Penetration): their work beyond the count, which grows with a profile's
  // vertices.
  std::uint64_t edge_tests = 0;

  // The narrow phase's elementary tests: every point and rim query and every
  // edge they examined. What a trial's contact work budget counts
  // (simulation/max_contact_tests): unlike the count of queries it tracks the
  // CPU they take whatever the profiles.
  std::uint64_t Tests() const { return point_queries + rim_queries + edge_tests; }
};

// A point where the moving part meets, or may meet within a step, a fixed
// part: a unilateral constraint of a nonsmooth stepper (docs/design.md
// decision 16). Its relative velocity is the moving part's at the point,
// v + w x r, read along the normal and two tangents the stepper chooses.
struct ContactPoint {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // moving origin to the point, world, m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, world: the way the fixed
                                                      // part pushes the moving one
  double gap = 0;  // signed distance along the normal, m; below 0: overlap
  double mu = 0;   // the pair's Coulomb coefficient
};

class ContactModel {
 public:
  virtual ~ContactModel() = default;

  // The contact forces on the moving part at `motion`, adding the work done to
  // `counters` when given. Same motion: the same bits, whatever else ran.
  // With `jacobian`, also their derivative in the same pass (the forces the
  // same bits as without).
  ContactForces Evaluate(const RigidMotion& motion, ContactCounters* counters = nullptr,
                         ContactJacobian* jacobian = nullptr) const {
    ContactCounters scratch;
    if (jacobian) *jacobian = ContactJacobian{};
    return DoEvaluate(motion, counters ? *counters : scratch, jacobian);
  }

  // For a nonsmooth stepper: appends to *points the model's contact points at
  // `motion` whose gap is below `margin` (m), adding the work to `counters`.
  // False when the model cannot: its contact is a penalty on sampled points,
  // not the exact geometry (a model of solids that are not both revolved).
  virtual bool AddContactPoints(const RigidMotion& motion, double margin,
                                ContactCounters& counters,
                                std::vector<ContactPoint>* points) const {
    (void)motion, (void)margin, (void)counters, (void)points;
    return false;
  }
  // For a nonsmooth stepper: the model's loads that stay smooth there (the
  // oil film, squeeze_film.h); none for a contact of solids. With
  // `jacobian` (zeroed by the caller), their derivative added to it.
  virtual ContactForces SmoothLoads(const RigidMotion& motion, ContactCounters& counters,
                                    ContactJacobian* jacobian) const {
    (void)motion, (void)counters, (void)jacobian;
    return {};
  }

 protected:
  // `jacobian`, when not null, starts at zero: add to it.
  virtual ContactForces DoEvaluate(const RigidMotion& motion, ContactCounters& counters,
                                   ContactJacobian* jacobian) const = 0;
};

}  // namespace vahf::contact
