// Penalty contact between one moving part and the static parts of a scene
// (docs/design.md decision 7): the moving part's point shell against each static
// part's exact signed distance, a normal pressure law that is C1 at contact
// onset with Hunt-Crossley dissipation, and regularised Coulomb friction.
//
// Normal pressure at penetration depth x (m), rate xdot (m/s):
//   p(x) = k x^2 / (2 x0)          for x < x0   (C1 onset: p(0) = p'(0) = 0)
//   p(x) = k (x - x0 / 2)          for x >= x0  (linear, slope k)
//   p    *= max(0, 1 + c xdot)                  (Hunt and Crossley, 1975)
// Friction on each point opposes its slip velocity v_t:
//   f = -mu |f_n| v_t / max(|v_t|, v_s)        (Coulomb above v_s, linear below)
// with the pair coefficient mu = 2 mu1 mu2 / (mu1 + mu2), the combination
// Simbody's contact forces use (SimTK ContactMaterial, HuntCrossleyForce).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "vahf/contact/contact_params.h"
#include "vahf/contact/point_shell.h"
#include "vahf/contact/signed_distance.h"

namespace vahf::contact {

// A static part: its shape's signed distance and where it stands.
struct Obstacle {
  SignedDistance field;
  Eigen::Isometry3d pose;  // part frame in the world
  double friction;         // its Coulomb coefficient
  double bounding_radius;  // about its frame origin, m
};

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
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m about the moving origin, world
  int points_in_contact = 0;
  double max_depth = 0.0;  // m
  bool in_contact() const { return points_in_contact > 0; }
};

// Work counters: what the broad phase saved and what the narrow phase did.
struct ContactCounters {
  std::uint64_t evaluations = 0;       // calls of Evaluate
  std::uint64_t pairs_skipped = 0;     // obstacle pairs rejected by bounding spheres
  std::uint64_t point_queries = 0;     // shell points tested against an obstacle
  std::uint64_t clusters_skipped = 0;  // shell tree nodes proven clear of an obstacle
};

class ContactModel {
 public:
  ContactModel(std::vector<ShellPoint> shell, double shell_bounding_radius,
               double moving_friction, std::vector<Obstacle> obstacles,
               const ContactParams& params);

  ContactForces Evaluate(const RigidMotion& motion) const;

  const ContactCounters& counters() const { return counters_; }
  const std::vector<ShellPoint>& shell() const { return shell_; }
  std::size_t obstacle_count() const { return obstacles_.size(); }

  // The normal pressure law alone (for tests), Pa.
  static double Pressure(const ContactParams& params, double depth, double depth_rate);

 private:
  // A bounding-sphere tree over the shell points (part frame), built once by
  // median splits along the longest box axis, stored in depth-first order
  // with an escape index, and the shell reordered so that every node covers a
  // contiguous run [begin, end). The signed distance is 1-Lipschitz, so a node
  // whose centre lies farther from an obstacle than its radius has no point
  // inside it and is skipped whole. Points are visited in (reordered) shell
  // order either way, so culling never changes a bit of the result.
  struct Node {
    Eigen::Vector3d centre;
    double radius;
    std::uint32_t begin, end;  // shell points covered
    std::uint32_t escape;      // next node when this one is skipped
  };
  static constexpr std::size_t kLeafSize = 32;
  void BuildTree(std::size_t begin, std::size_t end);

  std::vector<ShellPoint> shell_;
  std::vector<Node> nodes_;
  double shell_radius_;
  double moving_friction_;
  std::vector<Obstacle> obstacles_;
  ContactParams params_;
  mutable ContactCounters counters_;
};

}  // namespace vahf::contact
