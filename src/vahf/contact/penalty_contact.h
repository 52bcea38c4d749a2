// Penalty contact between one moving part and the static parts of a scene
// (docs/design.md decision 7): the moving part's point shell against each static
// part's exact signed distance, and each static part's convex edges (rims,
// rim.h) against the moving part's exact signed distance; a normal law that is
// C1 at contact onset with Hunt-Crossley dissipation, and regularised Coulomb
// friction.
//
// The law of each point, face or edge, is point_load.h's.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "vahf/contact/contact_jacobian.h"
#include "vahf/contact/contact_model.h"
#include "vahf/contact/contact_params.h"
#include "vahf/contact/point_load.h"
#include "vahf/contact/point_shell.h"
#include "vahf/contact/rim.h"
#include "vahf/contact/sector_bound.h"
#include "vahf/contact/signed_distance.h"

namespace vahf::contact {

// A static part: its shape's signed distance, where it stands, and its convex
// edges (MakeRims; empty: its edges are seen only by the moving shell).
struct Obstacle {
  SignedDistance field;
  Eigen::Isometry3d pose;     // part frame in the world
  double friction;            // its Coulomb coefficient
  double bounding_radius;     // about its frame origin, m
  std::vector<RimPoint> rim;  // in the part frame
};

class PenaltyContact final : public ContactModel {
 public:
  // The moving part: its point shell and its exact signed distance, both in
  // its own frame (the frame RigidMotion places), the radius of a sphere about
  // that frame's origin holding it, and its Coulomb coefficient.
  // `moving_rim`: the moving part's own convex edges (MakeRims, its frame),
  // queried against each obstacle's field with the line law, so that its
  // edges are seen where they are and not only by shell points half a
  // spacing inside them.
  PenaltyContact(std::vector<ShellPoint> shell, SignedDistance moving_field,
                 double moving_bounding_radius, double moving_friction,
                 std::vector<Obstacle> obstacles, const PenaltyLaw& params,
                 std::vector<RimPoint> moving_rim = {});

  const std::vector<ShellPoint>& shell() const { return shell_; }
  std::size_t obstacle_count() const { return obstacles_.size(); }

  // Rim points per culling block (see RimBlock).
  static constexpr std::size_t kRimBlockSize = 32;

 protected:
  ContactForces DoEvaluate(const RigidMotion& motion, ContactCounters& counters,
                           ContactJacobian* jacobian) const override;

 private:
  // A bounding-sphere tree over the shell points (part frame), built once by
  // median splits along the longest box axis, stored in depth-first order
  // with an escape index, and the shell reordered so that every node covers a
  // contiguous run [begin, end). The signed distance is 1-Lipschitz, so a node
  // whose centre lies farther from an obstacle than its radius has no point
  // inside it and is skipped whole; so is a node whose sector bound, carried
  // into a solid of revolution's meridian plane, misses its profile
  // (sector_bound.h: a peg's side against its bore's wall). Points are visited
  // in (reordered) shell order either way, so culling never changes a bit of
  // the result.
  struct Node {
    Eigen::Vector3d centre;
    double radius;
    SectorBound sector;
    std::uint32_t begin, end;  // shell points covered
    std::uint32_t escape;      // next node when this one is skipped
  };
  static constexpr std::size_t kLeafSize = 32;
  void BuildTree(std::size_t begin, std::size_t end);

  // An obstacle's rim points are culled in runs of kRimBlockSize consecutive
  // samples (in MakeRims order), each with a bounding sphere in the obstacle
  // frame, skipped whole when the moving part's signed distance at its centre
  // exceeds its radius (1-Lipschitz again) or its sector bound misses the
  // moving part's profile; all of them are skipped when the sphere about the
  // whole rim misses the moving part's bounding sphere. The points are visited
  // in order either way.
  struct RimBlock {
    Eigen::Vector3d centre;
    double radius;
    SectorBound sector;
    std::uint32_t begin, end;  // rim points covered
  };
  struct RimSet {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // about the whole rim
    double radius = 0;
    std::vector<RimBlock> blocks;
  };
  static RimSet BuildRimSet(const std::vector<RimPoint>& rim);

  // The moving part's rims against obstacle `index`'s field, with the moving
  // frame in the obstacle's and its meridian map (DoEvaluate's, for the shell).
  void EvaluateMovingRims(std::size_t index, const RigidMotion& motion,
                          const Eigen::Isometry3d& moving_in_obstacle,
                          const MeridianMap& to_obstacle, double mu,
                          ContactCounters& counters, ContactForces* out,
                          ContactJacobian* jacobian) const;
  // The obstacle's rim points against the moving part, after its shell points.
  void EvaluateRims(std::size_t index, const RigidMotion& motion, double mu,
                    ContactCounters& counters, ContactForces* out,
                    ContactJacobian* jacobian) const;

  std::vector<ShellPoint> shell_;
  std::vector<Node> nodes_;
  SignedDistance moving_field_;
  double shell_radius_;
  double moving_friction_;
  std::vector<Obstacle> obstacles_;
  std::vector<RimSet> rim_sets_;  // one per obstacle
  std::vector<RimPoint> moving_rim_;
  RimSet moving_rim_set_;
  PenaltyLaw params_;
};

}  // namespace vahf::contact
