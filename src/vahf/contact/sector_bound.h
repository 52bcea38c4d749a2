// A broad-phase bound for parts that turn about a common axis (docs/design.md
// decision 7; docs/physics.md, Meridian bounds). A bounding sphere cannot tell
// a peg's side from a bore wall 50 um away: every patch of the peg's side lies
// within its sphere's radius of the wall. In cylindrical coordinates about
// the points' own frame's z axis (radius rho, azimuth phi, height zeta) the
// patch is thin, though: all its points have rho = 10 mm. Carried into
// another part's frame by a rigid transform T, such a patch stays thin in
// that part's meridian coordinates (r = |p_xy|, z = p_z) when the two axes
// nearly coincide, and a solid of revolution can then be tested against it
// exactly (SignedDistance::MeridianBoxClear). The bound holds for any point
// set and any T; it is only useful when the axes are close.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace vahf::contact {

// Points in cylindrical coordinates about their frame's z axis: rho in
// [rho_min, rho_max], zeta in [zeta_min, zeta_max], and phi on the arc that
// runs counter-clockwise from the unit vector `from` to the unit vector `to`
// (both in the xy plane) through `width` radians. width >= 2 pi: any azimuth.
struct SectorBound {
  double rho_min = 0, rho_max = 0;
  double zeta_min = 0, zeta_max = 0;
  Eigen::Vector2d from = Eigen::Vector2d(1, 0), to = Eigen::Vector2d(1, 0);
  double width = 7.0;  // > 2 pi: the whole circle
};

// The least such bound of the points (their arc is the circle minus the widest
// gap between consecutive azimuths; a point on the axis has every azimuth).
// `points` must not be empty.
SectorBound BoundSector(const std::vector<Eigen::Vector3d>& points);

// A box in a solid of revolution's meridian half-plane: r in [r_min, r_max],
// z in [z_min, z_max].
struct MeridianBox {
  double r_min, r_max, z_min, z_max;
};

// The box of a sector bound under a transform T (p = A q + t), with what
// T contributes computed once per transform rather than once per cluster.
class MeridianMap {
 public:
  explicit MeridianMap(const Eigen::Isometry3d& t);

  // A box holding (|p_xy|, p_z) of p = T q for every q the bound holds,
  // widened by a margin far above the rounding of these sums (1e-9 m plus
  // 1e-12 of the magnitudes involved), so that a point the box excludes is
  // excluded whatever the rounding of the query's own transform.
  MeridianBox operator()(const SectorBound& s) const;

 private:
  Eigen::Vector2d bt_axis_, bt_offset_;  // B^T A_xy,z and B^T t_xy
  Eigen::Vector2d axis_xy_, offset_xy_;  // A_xy,z and t_xy
  Eigen::Vector2d c_;                    // (A_zx, A_zy)
  double c_norm_, one_minus_c2_, a_zz_, t_z_, t_norm_;
};

}  // namespace vahf::contact
