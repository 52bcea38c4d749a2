// Exact contact between a moving solid of revolution and fixed solids of
// revolution (docs/design.md decision 14; docs/physics.md, Contact): the
// point_load.h line law of each convex edge (rim circle, rim.h) of either
// part where it lies inside the other, integrated as a line load over the
// arcs in contact (rim_arcs.h), both ways: the moving part's rims against
// each fixed solid and each fixed part's rims against the moving solid.
// While the parts are rigid, two faces meet only through the rims that end
// them, so no face points are sampled: the cost of an evaluation is a few
// dozen profile queries, whatever the fit.
//
// Each arc is split at its deepest point (rim_arcs.h, DeepestAngle) and each
// side integrated by 4-point Gauss-Radau quadrature whose fixed node is the
// deepest point, so that the hardening barrier there is felt in full (7
// nodes an arc); a whole circle by the trapezoidal rule over kCircleNodes
// points from its deepest point. A node stands for its weight's length of
// rim, so the nodes' loads, friction and Jacobian are the general path's
// (penalty_contact.h) at those points.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "vahf/contact/contact_model.h"
#include "vahf/contact/contact_params.h"
#include "vahf/contact/rim.h"
#include "vahf/contact/rim_arcs.h"
#include "vahf/contact/signed_distance.h"

namespace vahf::contact {

// The depth difference over which a load's direction blends across a
// sharp edge's medial axis, m (SignedDistance::LoadNormal); 0: none. The
// profiles' corners are sharp, a machined edge is not (ISO 13715 states an
// edge's undefined shape in tenths of a millimetre); where a rim meets a
// solid near a corner, its deepest point lies on the medial axis, and a
// load along the nearest face's normal turns by the corner's angle within
// rounding of it (measured: 1 kN of a rod's wedged load turning by 45 deg
// within 4e-12 m, the integrator's steps falling to 10 ns). 1 um of depth
// difference turns it over about a micrometre of travel, far below the
// fits' 28-34 um clearances; used by the exact rim arcs below.
inline constexpr core::ParamDecl kEdgeBlend{
    "edge_blend",
    "m",
    core::ParamRule::kClosed,
    0,
    1e-3,
    1e-6,
    "depth difference over which a load's direction blends across a sharp edge's "
    "medial axis (resolving, revolved pairs)"};

class RevolvedContact final : public ContactModel {
 public:
  // A solid of revolution: its profile's exact field, its convex edges, and
  // (fixed parts) where it stands; its Coulomb coefficient and the radius of
  // a sphere about its frame origin holding it.
  struct Solid {
    SignedDistance field;
    std::vector<RimCircle> rims;
    Eigen::Isometry3d pose =
        Eigen::Isometry3d::Identity();  // fixed parts: part frame in the world
    double friction = 0;
    double bounding_radius = 0;
  };
  static Solid Make(const geometry::RevolvedProfile& profile,
                    const Eigen::Isometry3d& pose, double friction,
                    double bounding_radius);

  RevolvedContact(Solid moving, std::vector<Solid> fixed, const PenaltyLaw& params);

  static constexpr int kCircleNodes = 16;
  // A nonsmooth stepper's points on a whole circle within the margin: evenly
  // spaced from its deepest point.
  static constexpr int kCirclePoints = 8;

  // The exact geometry's contact points (docs/design.md decision 16): for
  // every rim arc within `margin` of the other solid, both ways, its deepest
  // point, and where it overlaps the solid the ends of each arc inside it
  // (the extent of the contact, which carries a moment); a whole circle,
  // kCirclePoints from its deepest point.
  bool AddContactPoints(const RigidMotion& motion, double margin,
                        ContactCounters& counters,
                        std::vector<ContactPoint>* points) const override;

 protected:
  ContactForces DoEvaluate(const RigidMotion& motion, ContactCounters& counters,
                           ContactJacobian* jacobian) const override;

 private:
  // One rim of `rims` (in `rim_to_field`'s source frame) against `field`:
  // `moving_rim` says whose rim it is (the point frame of contact_jacobian.h).
  struct Pass {
    const Solid& rims;
    const Solid& field;
    Eigen::Isometry3d rim_to_field;     // the rim part's frame in the field part's
    Eigen::Matrix3d field_to_world;     // rotation of the field part's frame
    Eigen::Isometry3d field_to_moving;  // the field part's frame in the moving part's
    bool moving_rim;
    double mu;
  };
  void EvaluatePass(const Pass& pass, const RigidMotion& m, ContactCounters& counters,
                    ContactForces* out, ContactJacobian* jacobian) const;
  // The passes of the fixed solids whose spheres lie within `margin` of the
  // moving one's, in order, two a solid (its rims against the moving solid's
  // field come second); the others counted as skipped.
  template <typename Visit>
  void ForEachPass(const RigidMotion& m, double margin, ContactCounters& counters,
                   Visit visit) const;
  void PassPoints(const Pass& pass, const RigidMotion& m, double margin,
                  ContactCounters& counters, std::vector<ContactPoint>* points) const;
  // The line load of one arc of `circle` (in the field's frame).
  void IntegrateArc(const Pass& pass, const PlacedCircle& circle, const NearEdges& solid,
                    const Arc& arc, const RigidMotion& m, ContactCounters& counters,
                    ContactForces* out, ContactJacobian* jacobian) const;

  Solid moving_;
  std::vector<Solid> fixed_;
  PenaltyLaw params_;
};

}  // namespace vahf::contact
