// A convex edge of one solid of revolution against another solid of
// revolution (docs/design.md decision 14): the rim circle, placed in the
// other solid's frame, meets the solid along arcs, found by a 1-D solve on
// the circle's angle, and its line load is integrated over each arc by
// Gauss-Radau quadrature. What the exact revolved contact
// (revolved_contact.h) is made of.
//
// The circle is P(phi) = centre + radius (x cos phi + y sin phi). The signed
// distance f(phi) of P(phi) to the solid depends only on P's meridian
// coordinates (r, z) = (|P_xy|, P_z), which move slowly along the circle when
// the two axes nearly coincide: |dz/dphi| <= radius sin(theta) and
// |dr/dphi| <= (|centre_xy| radius + radius^2 sin^2(theta) / 2) / r_min
// (theta the tilt between the circle's axis and the solid's, r_min the least
// radius of the circle's meridian trace), and f is 1-Lipschitz in (r, z). So
// f is sampled at kSamples angles; an interval whose ends lie farther from
// the surface than this bound lets f travel, or whose ends' tangents keep f
// on their side within its curvature bound, holds no crossing; an interval
// whose ends have opposite signs and on which f is monotone (its slopes at
// the ends and its curvature bound say so) holds one, found by Newton's
// method inside the bracket (f' = n . P', n the surface normal); and any
// other interval is halved, at most kMaxLevels times. In the finest
// interval a dip into the solid (or a gap out of it) whose ends' slopes
// bracket it is searched for as an arc's deepest point is (a rim crossing
// the other part's edge dips in a V narrower than the interval); another
// is shallower than the bound over the interval, about 0.2 um at the
// scenes' tilts of a degree, and is left out. The curvature bound adds the
// bend of the distance near the profile's corners (rim_arcs.cc,
// TravelBounds); where the trace reaches a corner, f has a kink, and the
// surface edges near it decide instead (rim_arcs.cc, EdgeLines; their lines
// have no kink): an interval holds no crossing when the trace can cross none
// of them, and one when it can cross only one edge, and that edge's line
// once. The queries examine only those edges (SignedDistance::Near).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "vahf/contact/sector_bound.h"
#include "vahf/contact/signed_distance.h"

namespace vahf::contact {

// A circle in the frame of the solid it is tested against.
struct PlacedCircle {
  Eigen::Vector3d centre;
  Eigen::Vector3d x, y;  // orthonormal: the circle's own x and y axes
  double radius = 0;     // m
  Eigen::Vector3d At(double phi) const {
    return centre + radius * (std::cos(phi) * x + std::sin(phi) * y);
  }
};

// An arc of angles [begin, end], end > begin, end - begin <= 2 pi (a whole
// circle when equal to it); begin may be negative.
struct Arc {
  double begin = 0, end = 0;
  bool whole() const;
};

// The least box (r, z) holding the circle's meridian trace in the solid's
// frame, widened by a margin far above the rounding of its sums.
MeridianBox TraceBox(const PlacedCircle& c);

// The solid as the circle can meet it: the edges near its trace box, the
// box widened by `margin` (m) on every side (InsideArcs' margin).
inline NearEdges NearCircle(const SignedDistance& solid, const PlacedCircle& c,
                            double margin = 0) {
  MeridianBox box = TraceBox(c);
  if (margin > 0) {
    box.r_min = std::max(0.0, box.r_min - margin);
    box.r_max += margin, box.z_min -= margin, box.z_max += margin;
  }
  return solid.Near(box);
}

inline constexpr int kMaxArcs = 8;

// The arcs of the circle inside the solid, in increasing angle, at most
// kMaxArcs (more are left out; two parts touch along at most a few); with a
// margin (m), the arcs closer to it than the margin (a nonsmooth stepper's
// candidate contacts). `solid` is NearCircle(the solid, c, margin). Adds the
// signed-distance queries it made to *queries and the profile edges they
// examined to *edges.
int InsideArcs(const PlacedCircle& c, const NearEdges& solid, Arc arcs[kMaxArcs],
               std::uint64_t* queries, std::uint64_t* edges, double margin = 0);

// The angle of an arc's deepest point, the least signed distance: where the
// distance's slope changes sign, by regula falsi (Illinois) from the arc's
// ends (a whole circle: from the samples either side of the least of
// kSamples), which also finds a kink where two faces meet; where the search
// stops on its tolerance, the zero of the slopes' chord over its last
// bracket. Counts as InsideArcs.
double DeepestAngle(const PlacedCircle& c, const NearEdges& solid, const Arc& arc,
                    std::uint64_t* queries, std::uint64_t* edges);

}  // namespace vahf::contact
