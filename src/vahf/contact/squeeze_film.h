// The oil film of a lubricated fit (docs/physics.md, Oiled fits): the
// squeeze-film force of the narrow annular gap between a cylindrical face of
// the moving solid of revolution and a facing cylindrical face of a fixed one
// (a piston in its barrel, a sleeve on a rod). The film resists the faces'
// lateral approach and their tilting; it does not resist axial sliding or
// spin (the viscous shear of those is left out: docs/physics.md says how
// small it is).
//
// Per unit of engaged length, at an axial station where the moving axis is
// offset by e from the fixed axis and moves laterally at de/dt, the
// long-bearing (Sommerfeld) solution of Reynolds' equation for a full,
// non-rotating film gives, with eps = |e| / c (derived in docs/physics.md):
//   along e:   f_r = -C0 / (1 - eps^2)^(3/2)               * de_r/dt
//   across e:  f_t = -C0 * 2 / ((2 + eps^2) sqrt(1 - eps^2)) * de_t/dt
//   C0 = 12 pi mu R^3 / c^3,
// R the film's radius, c the radial clearance, mu the oil's viscosity. A fit
// of engaged length L is neither long nor short: the centred damping of the
// short-bearing (Ocvirk) limit, C_s = pi mu R L^3 / c^3, and the long
// limit's, C_l = C0 L, are combined harmonically, C = C_s C_l / (C_s + C_l),
// which scales the local law by phi = L^2 / (L^2 + 12 R^2): the short limit
// for L << R, the long limit for L >> R. The film's thinnest gap is held
// above `film_floor` (a smooth cap of eps^2), below which the surfaces'
// roughness carries the load (mixed lubrication) and the penalty contact
// acts.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "vahf/contact/contact_model.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {

// A pair of facing cylindrical faces that holds an oil film: the moving
// face's radius and axial extent in the moving part's frame, the fixed
// face's in the fixed part's frame.
struct FilmFace {
  double radius = 0;                    // m, the film's mean radius
  double clearance = 0;                 // m, the radial gap when coaxial, > 0
  double moving_lo = 0, moving_hi = 0;  // m, along the moving part's axis
  double fixed_lo = 0, fixed_hi = 0;    // m, along the fixed part's axis
  Eigen::Isometry3d fixed_pose = Eigen::Isometry3d::Identity();  // fixed part, world
};

// The faces of `moving` and `fixed` (at `fixed_pose`) that face each other
// across a thin gap: one faces away from its axis and the other toward it,
// the outer radius exceeds the inner by c with 0 < c <= kThinFilm times
// their radius (Reynolds' thin-film approximation), whatever their axial
// overlap now.
inline constexpr double kThinFilm = 0.01;
std::vector<FilmFace> FilmFaces(const geometry::RevolvedProfile& moving,
                                const geometry::RevolvedProfile& fixed,
                                const Eigen::Isometry3d& fixed_pose);

struct FilmParams {
  double viscosity = 0;   // Pa s, the oil's dynamic viscosity
  double film_floor = 0;  // m, the thinnest film the law admits
};

// The squeeze-film force of a set of faces: `normal_force` and
// `friction_force` stay zero; the film's load is in `film_force` and its
// moment in `torque`; no point is counted as in contact.
class SqueezeFilm final : public ContactModel {
 public:
  SqueezeFilm(std::vector<FilmFace> faces, FilmParams params);

  const std::vector<FilmFace>& faces() const { return faces_; }

  // The film is smooth: a nonsmooth stepper takes its load as it is and
  // finds no contact point in it.
  bool AddContactPoints(const RigidMotion&, double, ContactCounters&,
                        std::vector<ContactPoint>*) const override {
    return true;
  }
  ContactForces SmoothLoads(const RigidMotion& motion, ContactCounters& counters,
                            ContactJacobian* jacobian) const override {
    return Evaluate(motion, &counters, jacobian);
  }

 protected:
  ContactForces DoEvaluate(const RigidMotion& motion, ContactCounters& counters,
                           ContactJacobian* jacobian) const override;

 private:
  std::vector<FilmFace> faces_;
  FilmParams params_;
};

// The smooth cap of eps^2 the film floor sets: q / (1 + (q / q_max)^16)^(1/16)
// with q_max = (1 - floor / c)^2 (floor < c: the registry refuses a floor at
// or above a film's clearance). Within 1 % of q below 0.85 q_max; it rises
// monotonically to q_max / 2^(1/16). The law uses the same cap.
double CappedEccentricitySquared(double q, double floor_over_clearance);

}  // namespace vahf::contact
