#include "vahf/contact/rim_arcs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vahf::contact {
namespace {

constexpr int kSamples = 8;      // f's first samples around the circle
constexpr int kMaxLevels = 10;   // halvings of an interval that may hold a dip
constexpr int kMaxNewton = 40;   // iterations of a bracketed root solve
constexpr int kMaxDeepest = 40;  // iterations of the deepest point's search
// The deepest point's search stops when f can change by less than this over
// its bracket (m): far below the micrometre bounds the barrier holds.
constexpr double kDeepestTolerance = 1e-10;

// The circle's points, signed distances and their slopes along the angle.
class CircleField {
 public:
  CircleField(const PlacedCircle& c, const SignedDistance& solid, std::uint64_t* queries,
              std::uint64_t* edges)
      : c_(c), solid_(solid), queries_(queries), edges_(edges) {}

  struct Value {
    double f;      // signed distance, m
    double slope;  // df/dphi, m/rad
  };
  Value operator()(double phi) const {
    const double cs = std::cos(phi), sn = std::sin(phi);
    const Eigen::Vector3d p = c_.centre + c_.radius * (cs * c_.x + sn * c_.y);
    ++*queries_;
    const Distance d = solid_.At(p, edges_);
    return {d.distance, c_.radius * d.normal.dot(cn_dot(cs, sn))};
  }

 private:
  Eigen::Vector3d cn_dot(double cs, double sn) const { return cs * c_.y - sn * c_.x; }
  const PlacedCircle& c_;
  const SignedDistance& solid_;
  std::uint64_t* queries_;
  std::uint64_t* edges_;
};

struct Sample {
  double phi;
  CircleField::Value v;
  bool inside() const { return v.f < 0; }
};

// The crossing in [a, b], whose ends are on opposite sides: Newton's method
// kept inside the bracket, halving where a step would leave it.
double Crossing(const CircleField& field, Sample a, Sample b) {
  const double width = b.phi - a.phi;
  double phi = a.phi - a.v.f * width / (b.v.f - a.v.f);  // the chord's root
  for (int i = 0; i < kMaxNewton; ++i) {
    const CircleField::Value v = field(phi);
    if (v.f == 0) return phi;
    if ((v.f < 0) == a.inside())
      a = {phi, v};
    else
      b = {phi, v};
    if (b.phi - a.phi < 1e-13 * width + 1e-15) break;
    double next = v.slope != 0 ? phi - v.f / v.slope : a.phi;
    if (!(next > a.phi && next < b.phi)) next = 0.5 * (a.phi + b.phi);
    if (std::abs(next - phi) < 1e-14) return next;
    phi = next;
  }
  return 0.5 * (a.phi + b.phi);
}

// Bounds on f's travel along the circle (rim_arcs.h).
struct Bounds {
  double slope;      // |df/dphi|, m/rad
  double curvature;  // an upper bound of d2f/dphi2, m/rad^2 (TravelBounds)
};

struct Scan {
  Scan(const CircleField& f, Bounds b) : field(f), bounds(b) {}
  const CircleField& field;
  Bounds bounds;
  double crossings[4 * kMaxArcs] = {};
  int count = 0;
  bool full = false;

  void Add(double phi) {
    if (count < 4 * kMaxArcs)
      crossings[count++] = phi;
    else
      full = true;
  }
  // The crossings in (a, b], in order.
  void Interval(const Sample& a, const Sample& b, int level) {
    if (a.inside() != b.inside()) {
      Add(Crossing(field, a, b));
      return;
    }
    // f cannot leave its side and come back over the interval: by its
    // slope bound, or by its curvature bound (f stays within K w^2 / 8 of
    // the chord, w the interval's width, K >= |f''| on it: TravelBounds).
    const double w = b.phi - a.phi;
    const double fa = std::abs(a.v.f), fb = std::abs(b.v.f);
    if (fa + fb > bounds.slope * w || std::min(fa, fb) > 0.125 * bounds.curvature * w * w)
      return;
    if (level >= kMaxLevels) return;  // a dip shallower than the bound: left out
    const double mid = 0.5 * (a.phi + b.phi);
    const Sample m{mid, field(mid)};
    Interval(a, m, level + 1);
    Interval(m, b, level + 1);
  }
};

// Bounds on |d(r, z)/dphi| and |d2(r, z)/dphi2| along the circle (rim_arcs.h),
// with e = P_xy - centre_xy, |e'|^2 - |e|^2 <= rho^2 sin^2(theta) and
// r r'' = |e'|^2 - |e|^2 - centre_xy . e - r'^2. f = D(r, z), D the profile's
// signed distance, so f'' = (r, z)'^T H (r, z)' + grad D . (r, z)'': along
// a face H = 0; `corner` (m) from the nearest corner of the profile, the
// distance to a corner point adds at most |(r, z)'|^2 / corner either way
// (SignedDistance::CornerDistance), and a trace that reaches a corner meets
// D's kink there, which no curvature bounds (infinity).
Bounds TravelBounds(const PlacedCircle& c, double r_min, double corner) {
  const Eigen::Vector3d n = c.x.cross(c.y);
  const double sin2 = std::max(0.0, 1.0 - n.z() * n.z());
  const double rho = c.radius, off = c.centre.head<2>().norm();
  double dr = rho, ddr = rho + off;
  if (r_min > 0) {
    dr = std::min(rho, (off * rho + 0.5 * rho * rho * sin2) / r_min);
    ddr = std::min(ddr, (rho * rho * sin2 + off * rho + dr * dr) / r_min);
  }
  const double dz = rho * std::sqrt(sin2);  // |z'| and |z''| alike
  const double slope = 1.01 * std::hypot(dr, dz) + 1e-12 * rho;
  const double curvature =
      corner > 0 ? 1.01 * std::hypot(ddr, dz) + 1e-12 * rho + slope * slope / corner
                 : std::numeric_limits<double>::infinity();
  return {slope, curvature};
}

}  // namespace

bool Arc::whole() const { return end - begin >= 2 * M_PI; }

MeridianBox TraceBox(const PlacedCircle& c) {
  const Eigen::Vector3d n = c.x.cross(c.y);
  const double sin_tilt = std::sqrt(std::max(0.0, 1.0 - n.z() * n.z()));
  const double rho = c.radius, off = c.centre.head<2>().norm();
  const double margin = 1e-9 + 1e-12 * (rho + c.centre.norm());
  return {std::max(0.0, rho * std::abs(n.z()) - off) - margin, rho + off + margin,
          c.centre.z() - rho * sin_tilt - margin, c.centre.z() + rho * sin_tilt + margin};
}

int InsideArcs(const PlacedCircle& c, const SignedDistance& solid, Arc arcs[kMaxArcs],
               std::uint64_t* queries, std::uint64_t* edges) {
  const MeridianBox box = TraceBox(c);
  if (solid.MeridianBoxClear(box)) return 0;
  const CircleField field(c, solid, queries, edges);
  Scan scan(field, TravelBounds(c, std::max(0.0, box.r_min), solid.CornerDistance(box)));
  const double step = 2 * M_PI / kSamples;
  const Sample first{0.0, field(0.0)};
  Sample a = first;
  for (int k = 1; k <= kSamples; ++k) {
    const Sample b =
        k == kSamples ? Sample{2 * M_PI, first.v} : Sample{k * step, field(k * step)};
    scan.Interval(a, b, 0);
    a = b;
  }
  if (scan.count == 0) {
    if (!first.inside()) return 0;
    arcs[0] = {0.0, 2 * M_PI};
    return 1;
  }
  // Crossings alternate sides; an odd count means one was left out: then
  // every span between crossings is judged at its middle.
  const double* x = scan.crossings;
  const int n = scan.count;
  int out = 0;
  const auto add = [&](double begin, double end) {
    if (out < kMaxArcs && end > begin) arcs[out++] = {begin, end};
  };
  if (n % 2 == 0 && !scan.full) {
    // Inside at 0: the spans (x[n-1] - 2 pi, x[0]), (x[1], x[2]), ...;
    // outside: (x[0], x[1]), (x[2], x[3]), ...
    if (first.inside()) {
      add(x[n - 1] - 2 * M_PI, x[0]);
      for (int i = 1; i + 1 < n; i += 2) add(x[i], x[i + 1]);
    } else {
      for (int i = 0; i + 1 < n; i += 2) add(x[i], x[i + 1]);
    }
    return out;
  }
  for (int i = 0; i < n; ++i) {
    const double begin = x[i], end = i + 1 < n ? x[i + 1] : x[0] + 2 * M_PI;
    if (field(0.5 * (begin + end)).f < 0) add(begin, end);
  }
  return out;
}

double DeepestAngle(const PlacedCircle& c, const SignedDistance& solid, const Arc& arc,
                    std::uint64_t* queries, std::uint64_t* edges) {
  const CircleField field(c, solid, queries, edges);
  double lo = arc.begin, hi = arc.end;
  if (arc.whole()) {  // bracket the least of kSamples samples
    double x0 = lo, least = field(lo).f;
    for (int k = 1; k < kSamples; ++k) {
      const double phi = arc.begin + 2 * M_PI * k / kSamples;
      const double f = field(phi).f;
      if (f < least) least = f, x0 = phi;
    }
    lo = x0 - 2 * M_PI / kSamples, hi = x0 + 2 * M_PI / kSamples;
  }
  CircleField::Value a = field(lo), b = field(hi);
  const auto lower = [&] { return a.f <= b.f ? lo : hi; };
  if (!(a.slope < 0 && b.slope > 0)) return lower();  // no interior minimum bracketed
  // The slope changes sign at the minimum. Where the rim crosses the solid's
  // medial axis (equally deep under two faces) f has a kink there, a V;
  // elsewhere a smooth bowl. A secant of the slope (regula falsi) finds a
  // bowl's bottom, and the meeting point of the ends' tangents a V's point
  // once the ends lie on its straight arms; either creeps when an end is
  // far out on a curved arm. So the steps cycle: a secant, a meeting point,
  // and a bisection when those two did not halve the bracket (Dekker's
  // safeguard: the bracket halves at least every third query), else a
  // second meeting point. A meeting point is kept a hair inside the
  // bracket: a V's point found at an end, its slope one arm's, is then
  // bracketed by the probe beside it and the bracket closes to the
  // tolerance. It stops when f can change by less than kDeepestTolerance
  // over the bracket (f convex on it, the premise of the search: its slope
  // lies between the ends').
  double checkpoint = hi - lo;  // the bracket's width at the cycle's start
  for (int i = 0; i < kMaxDeepest; ++i) {
    if ((hi - lo) * std::max(-a.slope, b.slope) < kDeepestTolerance) break;
    const int phase = i % 3;
    if (phase == 0) checkpoint = hi - lo;
    double x;
    if (phase == 0) {
      x = lo - a.slope * (hi - lo) / (b.slope - a.slope);
    } else if (phase == 2 && hi - lo > 0.5 * checkpoint) {
      x = 0.5 * (lo + hi);
    } else {
      const double hair = 0.5 * kDeepestTolerance / std::max(-a.slope, b.slope);
      const double meet = (b.f - a.f + a.slope * lo - b.slope * hi) / (a.slope - b.slope);
      x = std::min(std::max(meet, lo + hair), hi - hair);
    }
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const CircleField::Value v = field(x);
    if (v.slope < 0) {
      lo = x, a = v;
    } else if (v.slope > 0) {
      hi = x, b = v;
    } else {
      return x;
    }
  }
  return lower();
}

}  // namespace vahf::contact
