// Samples of a solid's convex edges ("rims"), the static side of edge contact
// (docs/design.md decision 7, docs/physics.md, Contact). The moving part's point
// shell cannot see a static part's edge: a bore's rim can sink between two
// shell points of the moving part. Each rim sample is therefore also queried
// against the moving part's exact signed distance, and carries the length of
// edge it stands for, so that summing a line load * length over the samples
// integrates it along the edge whatever the spacing.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "vahf/core/param_decl.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {

struct RimPoint {
  Eigen::Vector3d position;  // on the edge, in the part frame, m
  double length;             // of edge it stands for, m
};

// A profile vertex is a convex edge when the polygon turns left there (it is
// counter-clockwise) by more than this, i.e. its interior angle is below
// 179 deg. A blunter edge is all but flat: a face pressed on it is wider than
// a shell spacing and the point shell resolves it; roundoff-straight vertices
// (a profile edge split in two) must give no rim at all.
inline constexpr double kMinRimTurnRad = M_PI / 180.0;

// A solid of revolution's convex edge: the circle of a profile vertex off the
// axis whose interior angle is below 179 deg, in the part frame.
struct RimCircle {
  double radius;  // m, > 0
  double height;  // z, m
};
// The convex edges of a profile, in its vertex order.
std::vector<RimCircle> RimCircles(const geometry::RevolvedProfile& profile);

// Spacing of the samples along the static parts' convex edges, m.
inline constexpr core::ParamDecl kRimSpacing{
    "rim_spacing",
    "m",
    core::ParamRule::kClosed,
    1e-5,
    1,
    0.5e-3,
    "sample spacing along the parts' convex edges (rims; at most 1e6 samples)"};

// Line load per metre of penetration per metre of a static part's convex
// edge, N/m per m = Pa. The default is the face law's stiffness over
// a strip one shell spacing wide, 1e10 Pa/m * 1e-3 m: an edge pressed into
// the moving part is about as stiff as the 1 mm patches of shell along it
// would be if they saw it. Like the face law it is a numerical penalty, far
// softer than steel: the load per unit length per unit approach of an elastic
// line contact is of the order of the contact modulus, up to a logarithm of
// the contact width (K. L. Johnson, Contact Mechanics, Cambridge University
// Press 1985, two-dimensional contact of cylinders), and steel on steel has
// E* = E / (2 (1 - nu^2)) = 1.15e11 Pa for E = 210 GPa, nu = 0.3.
inline constexpr core::ParamDecl kLineStiffness{
    "line_stiffness",
    "Pa",
    core::ParamRule::kClosed,
    1,
    1e13,
    1e7,
    "line load per metre of penetration per metre of a static part's convex edge"};

// For a solid of revolution: each profile vertex off the axis (r > 0) whose
// interior angle is below 179 deg gives a circle of n = ceil(2 pi r / spacing)
// samples at azimuths 2 pi (j + 1/2) / n, each of length 2 pi r / n. Straight
// and concave vertices (a bore's bottom corner) give none, nor does the axis.
// For a box: its 12 edges, each split into ceil(L / spacing) equal segments
// sampled at their midpoints, each of the segment's length. Circles and edges
// come one after the other, each a run of consecutive samples. A count that is
// an integer to within 1e-9 is not rounded up (10 mm at 1 mm gives 10).
std::vector<RimPoint> MakeRims(const geometry::Shape& shape, double spacing);

// The most samples MakeRims can make, computed without making them (in
// double): checked against kMaxRimPoints before any allocation.
double RimSizeBound(const geometry::Shape& shape, double spacing);

// Each rim sample is a signed-distance query per contact evaluation, like a
// shell point (point_shell.h, kMaxShellPoints).
inline constexpr double kMaxRimPoints = 1e6;

}  // namespace vahf::contact
