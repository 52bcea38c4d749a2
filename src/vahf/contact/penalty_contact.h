// Penalty contact between one moving part and the static parts of a scene
// (docs/design.md decision 7): the moving part's point shell against each static
// part's exact signed distance, and each static part's convex edges (rims,
// rim.h) against the moving part's exact signed distance; a normal law that is
// C1 at contact onset with Hunt-Crossley dissipation, and regularised Coulomb
// friction.
//
// Normal pressure at penetration depth x (m), rate xdot (m/s):
//   e(x) = k x^2 / (2 x0)          for x < x0   (C1 onset: e(0) = e'(0) = 0)
//   e(x) = k (x - x0 / 2)          for x >= x0  (linear, slope k)
//   p(x) = e(x) / (1 - x / b)^2                 (hardening barrier at depth b)
//   p    *= max(0, 1 + c xdot)                  (Hunt and Crossley, 1975)
// The barrier makes the stiffness rise without bound as the depth nears b, so
// the penetration stays below b under any load the integrator resolves: the
// energy stored by the time x reaches b (1 - eps) grows like k b^2 / eps (an
// inverse-square barrier in the spirit of incremental potential contact: M.
// Li et al., ACM Trans. Graph. 39(4) 49, 2020). Past x_c = b (1 - eps),
// eps = kBarrierReserve, the law continues along its tangent (C1), for a
// trial step that overshoots. b = 0: no barrier, the law stays linear. A
// trial sets b to the penetration bound (contact_params.h).
// A rim point x deep inside the moving part carries the same law per metre of
// edge with line_stiffness for k (N/m per m), times the length it stands for,
// and pushes the moving part along minus its outward normal there; xdot is
// then the moving material's velocity there along that normal.
// Friction on each point (shell or rim) opposes the moving material's slip
// velocity v_t there:
//   f = -mu |f_n| v_t / max(|v_t|, v_s)        (Coulomb above v_s, linear below)
// with the pair coefficient mu = 2 mu1 mu2 / (mu1 + mu2), the combination
// Simbody's contact forces use (SimTK ContactMaterial, HuntCrossleyForce).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "vahf/contact/contact_jacobian.h"
#include "vahf/contact/contact_model.h"
#include "vahf/contact/contact_params.h"
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
               std::vector<Obstacle> obstacles, const ContactParams& params,
               std::vector<RimPoint> moving_rim = {});

  const std::vector<ShellPoint>& shell() const { return shell_; }
  std::size_t obstacle_count() const { return obstacles_.size(); }

  // A law's slopes: per metre of depth and per m/s of depth rate.
  struct Slopes {
    double depth = 0, rate = 0;
  };
  // The normal pressure law alone (for tests), Pa; with `slopes`, also its
  // derivatives (the value the same bits).
  static double Pressure(const ContactParams& params, double depth, double depth_rate,
                         Slopes* slopes = nullptr);
  // The rim's line law alone (for tests), N/m: Pressure with line_stiffness.
  static double LineLoad(const ContactParams& params, double depth, double depth_rate,
                         Slopes* slopes = nullptr);
  // Rim points per culling block (see RimBlock).
  static constexpr std::size_t kRimBlockSize = 32;
  // The barrier's reserve eps: the law leaves the barrier for its tangent at
  // depth b (1 - eps), where it is 1 / eps^2 = 1e6 times the linear law.
  static constexpr double kBarrierReserve = 1e-3;

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

  // The law shared by faces and rims: stiffness k, onset x0, dissipation c;
  // its slopes too when `slopes` is given.
  static double Law(double k, double x0, double c, double barrier, double depth,
                    double depth_rate, Slopes* slopes);
  // Adds a normal force fn pushing the moving part along the world unit vector
  // u at r (world, from its origin), and the friction against the moving
  // material's velocity v there; false (nothing added) when fn is not positive.
  bool AddContact(const Eigen::Vector3d& r, const Eigen::Vector3d& v,
                  const Eigen::Vector3d& u, double fn, double mu,
                  ContactForces* out) const;
  // One point at `depth` with its face (area, Pressure) or line (length,
  // LineLoad) law: AddContact and, with `jacobian`, its derivative
  // (contact_jacobian.h; w the part's angular velocity).
  bool AddPoint(const Eigen::Vector3d& r, const Eigen::Vector3d& v, const Eigen::Vector3d& u,
                double depth, bool line, double size, double mu, PointFrame frame,
                const Eigen::Vector3d& w, ContactForces* out, ContactJacobian* jacobian) const;
  // The moving part's rims against obstacle `index`'s field, with the moving
  // frame in the obstacle's and its meridian map (DoEvaluate's, for the shell).
  void EvaluateMovingRims(std::size_t index, const RigidMotion& motion,
                          const Eigen::Isometry3d& moving_in_obstacle,
                          const MeridianMap& to_obstacle, double mu, ContactCounters& counters,
                          ContactForces* out, ContactJacobian* jacobian) const;
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
  ContactParams params_;
};

}  // namespace vahf::contact
