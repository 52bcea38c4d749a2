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
// A crossing is where f is within this of zero (m): its angle is then within
// 1e-12 m / |f'| of the root, and the line load there, which vanishes at the
// root with its slope (the law's C1 onset), is left out over at most that.
constexpr double kCrossingTolerance = 1e-12;

// The circle's points, signed distances and their slopes along the angle.
class CircleField {
 public:
  // f is the signed distance less `margin` (InsideArcs).
  CircleField(const PlacedCircle& c, const NearEdges& solid, std::uint64_t* queries,
              std::uint64_t* edges, double margin = 0)
      : c_(c), solid_(solid), queries_(queries), edges_(edges), margin_(margin) {}

  struct Value {
    double f;            // signed distance (less the margin), m
    double slope;        // df/dphi, m/rad
    Eigen::Vector2d q;   // the point's meridian coordinates (r, z), m
    Eigen::Vector2d dq;  // their slopes d(r, z)/dphi, m/rad (the scan's only)
  };
  // At an angle, for the solves (the crossings, the deepest points), which
  // need no slopes of the trace.
  Value operator()(double phi) const {
    return Query(std::cos(phi), std::sin(phi), false);
  }
  // At the angle whose cosine and sine are cs and sn, with the trace's slopes
  // (the scan's tests).
  Value At(double cs, double sn) const { return Query(cs, sn, true); }
  const NearEdges& solid() const { return solid_; }
  double margin() const { return margin_; }

 private:
  Value Query(double cs, double sn, bool trace_slopes) const {
    const Eigen::Vector3d p = c_.centre + c_.radius * (cs * c_.x + sn * c_.y);
    ++*queries_;
    Eigen::Vector2d q;
    const Distance d = solid_.At(p, edges_, &q);
    const Eigen::Vector3d t = cs * c_.y - sn * c_.x;  // dP/dphi over the radius
    Value v{d.distance - margin_, c_.radius * d.normal.dot(t), q,
            Eigen::Vector2d::Zero()};
    if (trace_slopes) {
      const Eigen::Vector3d dp = c_.radius * t;
      // r' = (P_xy . P'_xy) / r; on the axis, where r has no slope, 0.
      v.dq = {q.x() > 0 ? (p.x() * dp.x() + p.y() * dp.y()) / q.x() : 0.0, dp.z()};
    }
    return v;
  }

  const PlacedCircle& c_;
  const NearEdges& solid_;
  std::uint64_t* queries_;
  std::uint64_t* edges_;
  double margin_;
};

struct Sample {
  double phi;
  CircleField::Value v;
  bool inside() const { return v.f < 0; }
};

// The scan's angles are the kSamples equally spaced ones and the midpoints
// of their halvings, whose cosine and sine follow from their ends': for
// angles a and b, w = b - a, cos((a + b) / 2) = (cos a + cos b) / (2 cos(w / 2))
// and likewise the sine, which spares a scan query's sincos (a tenth of a
// trial's CPU) at a rounding of an ulp a halving.
struct Unit {
  double cs, sn;
};
struct ScanAngles {
  Unit sample[kSamples + 1];    // at 2 pi k / kSamples
  double half[kMaxLevels + 1];  // 1 / (2 cos(w / 2)) for w = 2 pi / kSamples / 2^level
};
const ScanAngles kScanAngles = [] {
  ScanAngles a;
  const double step = 2 * M_PI / kSamples;
  for (int k = 0; k <= kSamples; ++k)
    a.sample[k] = {std::cos(k * step), std::sin(k * step)};
  for (int level = 0; level <= kMaxLevels; ++level)
    a.half[level] = 0.5 / std::cos(0.5 * std::ldexp(step, -level));
  return a;
}();

// The crossing in [a, b], whose ends are on opposite sides: Newton's method
// kept inside the bracket, halving where a step would leave it.
double Crossing(const CircleField& field, Sample a, Sample b) {
  const double width = b.phi - a.phi;
  // The first guess: a Newton step from the end nearer the surface, whose
  // slope the scan has, when it stays inside; otherwise the chord's root.
  const Sample& near = std::abs(a.v.f) < std::abs(b.v.f) ? a : b;
  double phi = near.v.slope != 0 ? near.phi - near.v.f / near.v.slope : a.phi;
  if (!(phi > a.phi && phi < b.phi)) phi = a.phi - a.v.f * width / (b.v.f - a.v.f);
  for (int i = 0; i < kMaxNewton; ++i) {
    const CircleField::Value v = field(phi);
    if (v.f == 0) return phi;
    if ((v.f < 0) == a.inside())
      a = {phi, v};
    else
      b = {phi, v};
    if (b.phi - a.phi < 1e-13 * width + 1e-15) break;
    double next = v.slope != 0 ? phi - v.f / v.slope : a.phi;
    // Within kCrossingTolerance of the surface, the Newton step's end, not
    // queried: Newton's method converges quadratically there, and the next
    // query would only confirm it. Not the bracket's middle: a step from an
    // end of the bracket that lands on that end (f there within rounding of
    // zero) is no sign of a bracket too wide (it put arcs' ends up to half
    // the scan's finest interval off, 0.6 um deep in a trial).
    if (std::abs(v.f) < kCrossingTolerance)
      return next >= a.phi && next <= b.phi ? next : phi;
    if (!(next > a.phi && next < b.phi)) next = 0.5 * (a.phi + b.phi);
    if (std::abs(next - phi) < 1e-14) return next;
    phi = next;
  }
  return 0.5 * (a.phi + b.phi);
}

// The least of s f between samples a and b (s = 1: f's minimum, s = -1: its
// maximum), a sample of the search's bracket when no interior extremum is
// bracketed (the slopes of s f must change sign from a to b). When the
// search stops on its tolerance, `chord` (if given) is set to where the
// chord of the slopes over its last bracket crosses zero.
Sample Extremum(const CircleField& field, Sample a, Sample b, double s,
                double* chord = nullptr) {
  double lo = a.phi, hi = b.phi;
  const auto lower = [&] { return s * a.v.f <= s * b.v.f ? a : b; };
  if (!(s * a.v.slope < 0 && s * b.v.slope > 0)) return lower();  // none bracketed
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
    const double sa = s * a.v.slope, sb = s * b.v.slope;
    if ((hi - lo) * std::max(-sa, sb) < kDeepestTolerance) break;
    const int phase = i % 3;
    if (phase == 0) checkpoint = hi - lo;
    double x;
    if (phase == 0) {
      x = lo - sa * (hi - lo) / (sb - sa);
    } else if (phase == 2 && hi - lo > 0.5 * checkpoint) {
      x = 0.5 * (lo + hi);
    } else {
      const double hair = 0.5 * kDeepestTolerance / std::max(-sa, sb);
      const double meet = (s * b.v.f - s * a.v.f + sa * lo - sb * hi) / (sa - sb);
      x = std::min(std::max(meet, lo + hair), hi - hair);
    }
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const Sample v{x, field(x)};
    if (s * v.v.slope < 0) {
      lo = x, a = v;
    } else if (s * v.v.slope > 0) {
      hi = x, b = v;
    } else {
      return v;
    }
  }
  // *chord: where the slope's chord crosses zero in the last bracket.
  if (chord && s * a.v.slope < 0 && s * b.v.slope > 0) {
    const double sa = s * a.v.slope, sb = s * b.v.slope;
    *chord = std::min(std::max(lo - sa * (hi - lo) / (sb - sa), lo), hi);
  }
  return lower();
}

// Whether a function of magnitudes fa and fb (> 0) at the ends of an
// interval of width w, its slope and curvature at most s and k on it, cannot
// reach zero inside: by its slope bound, or because it stays within
// k w^2 / 8 of its chord.
bool CannotReachZero(double fa, double fb, double s, double k, double w) {
  return fa + fb > s * w || std::min(fa, fb) > 0.125 * k * w * w;
}

// Whether a function g with values ga and gb (the same strict sign) and
// slopes sa and sb at the ends of an interval of width w, its curvature at
// most k on it, keeps its sign inside, by its tangents at the ends: by
// Taylor's theorem g (for ga, gb > 0) stays above ga + sa t - k t^2 / 2 from
// the first end to the middle (t from 0 to w / 2), a concave function of t,
// so above the lesser of ga and its value at the middle; likewise from the
// other end. Where the ends' slopes point away from zero this holds over
// intervals far wider than the chord's bound (CannotReachZero) allows.
bool TangentsKeepSide(double ga, double sa, double gb, double sb, double k, double w) {
  if (ga < 0 && gb < 0) ga = -ga, sa = -sa, gb = -gb, sb = -sb;
  const double bend = 0.125 * k * w * w;
  return ga > 0 && gb > 0 && ga + 0.5 * w * sa > bend && gb - 0.5 * w * sb > bend;
}

// Whether g, with values ga and gb and slopes sa and sb at the ends of an
// interval of width w, its curvature at most k on it, is monotone there: its
// slope has the sign of gb - ga at both ends, and it stays above the lower of
// the lines s_a - k t and s_b - k (w - t), whose meeting point is
// (s_a + s_b - k w) / 2 over zero. With ends on opposite sides, g then
// crosses zero once.
bool Monotone(double ga, double sa, double gb, double sb, double k, double w) {
  const double s = gb > ga ? 1.0 : -1.0;
  sa *= s, sb *= s;
  return sa > 0 && sb > 0 && sa + sb > k * w;
}

// Bounds on the travel of the circle's meridian trace (r, z)(phi) and of f
// along it (TravelBounds).
struct Bounds {
  double dr, dz;     // |r'|, |z'| (and |z''|), m/rad
  double ddr;        // |r''|, m/rad^2
  double slope;      // |df/dphi|, m/rad
  double curvature;  // an upper bound of d2f/dphi2, m/rad^2
};

// A surface edge near the circle's trace (NearEdges), as the scan tests it:
// the trace crosses the surface only where it crosses one of these edges, at
// a root of its line's function L = n . (q - a) (n the outward normal) with
// P = u . (q - a) in [0, length] (u along the edge). Both are smooth along
// the circle, with no kink at the profile's corners, |L'| <= |n_r| |r'| +
// |n_z| |z'| and |L''| <= |n_r| |r''| + |n_z| |z''|, and P likewise with u.
struct EdgeLines {
  struct Line {
    Eigen::Vector2d a, n, u;
    double length;
    double slope_l, curve_l, slope_p, curve_p;
  };
  Line line[NearEdges::kMaxEdges];
  int count = 0;  // 0: the solid's edges are not listed, no line test

  EdgeLines(const NearEdges& solid, const Bounds& b) {
    if (solid.count() < 0) return;
    count = solid.count();
    const auto along = [&](const Eigen::Vector2d& v, double dr, double dz) {
      return 1.01 * (std::abs(v.x()) * dr + std::abs(v.y()) * dz) + 1e-15;
    };
    for (int k = 0; k < count; ++k) {
      const ProfileEdge& e = solid.edge(k);
      const Eigen::Vector2d u(-e.outward.y(), e.outward.x());
      line[k] = {e.a,
                 e.outward,
                 u,
                 std::sqrt(e.ab2),
                 along(e.outward, b.dr, b.dz),
                 along(e.outward, b.ddr, b.dz),
                 along(u, b.dr, b.dz),
                 along(u, b.ddr, b.dz)};
    }
  }

  // Whether g, of slope and curvature at most s and k, keeps the sign it
  // has at both ends (ga, gb, same strict sign; slopes sa, sb) over an
  // interval of width w.
  static bool KeepsSide(double ga, double sa, double gb, double sb, double s, double k,
                        double w) {
    if (!((ga > 0 && gb > 0) || (ga < 0 && gb < 0))) return false;
    return CannotReachZero(std::abs(ga), std::abs(gb), s, k, w) ||
           TangentsKeepSide(ga, sa, gb, sb, k, w);
  }
  // Whether the trace cannot reach the edge of `l` between the circle's
  // values a and b, an interval of width w apart: it stays on one side of
  // the edge's line, or before its start or past its end along it.
  static bool Misses(const Line& l, const CircleField::Value& a,
                     const CircleField::Value& b, double w) {
    const Eigen::Vector2d da = a.q - l.a, db = b.q - l.a;
    if (KeepsSide(l.n.dot(da), l.n.dot(a.dq), l.n.dot(db), l.n.dot(b.dq), l.slope_l,
                  l.curve_l, w))
      return true;
    const double pa = l.u.dot(da), pb = l.u.dot(db);
    const double sa = l.u.dot(a.dq), sb = l.u.dot(b.dq);
    if (pa < 0 && KeepsSide(pa, sa, pb, sb, l.slope_p, l.curve_p, w)) return true;
    return pa > l.length &&
           KeepsSide(pa - l.length, sa, pb - l.length, sb, l.slope_p, l.curve_p, w);
  }
  // Whether the trace cannot cross any of the edges between the circle's
  // values a and b, an interval of width w apart.
  bool NoneCrossed(const CircleField::Value& a, const CircleField::Value& b,
                   double w) const {
    if (count == 0) return false;
    for (int k = 0; k < count; ++k)
      if (!Misses(line[k], a, b, w)) return false;
    return true;
  }
  // Whether the trace, from a to b (on opposite sides of the surface, w
  // apart), crosses the surface once: it misses every edge but one, and
  // crosses that edge's line once (its line function is monotone there,
  // Monotone: it has no kink at the profile's corners, as f has). Every
  // point where f changes sign lies on the surface, so on that edge's line,
  // and the trace meets the line once. Near a corner f's curvature has no
  // bound, Monotone cannot tell, and this spares the scan's halvings down to
  // its finest interval at each end of every arc there.
  bool OneCrossed(const CircleField::Value& a, const CircleField::Value& b,
                  double w) const {
    if (count == 0) return false;
    const Line* only = nullptr;
    for (int k = 0; k < count; ++k) {
      if (Misses(line[k], a, b, w)) continue;
      if (only) return false;
      only = &line[k];
    }
    if (!only) return false;
    const double la = only->n.dot(a.q - only->a), lb = only->n.dot(b.q - only->a);
    return ((la < 0 && lb > 0) || (la > 0 && lb < 0)) &&
           Monotone(la, only->n.dot(a.dq), lb, only->n.dot(b.dq), only->curve_l, w);
  }
};

struct Scan {
  // With a margin the crossings lie on the surface's offset, which near a
  // corner follows no edge's line: no line test then.
  Scan(const CircleField& f, const Bounds& b) : field(f), bounds(b), lines(f.solid(), b) {
    if (f.margin() != 0) lines.count = 0;
  }
  const CircleField& field;
  Bounds bounds;
  EdgeLines lines;
  double crossings[4 * kMaxArcs] = {};
  int count = 0;
  bool full = false;

  void Add(double phi) {
    if (count < 4 * kMaxArcs)
      crossings[count++] = phi;
    else
      full = true;
  }
  // The crossings in (a, b], in order; ua and ub the ends' cosine and sine,
  // b - a = 2 pi / kSamples / 2^level.
  void Interval(const Sample& a, const Unit& ua, const Sample& b, const Unit& ub,
                int level) {
    const double w = b.phi - a.phi;
    if (a.inside() != b.inside()) {
      // Ends on opposite sides hold an odd number of crossings: one when f
      // is monotone over the interval (Monotone), or when the trace crosses
      // the surface once (EdgeLines::OneCrossed: near a corner, where f has
      // a kink), or when the interval is as fine as the scan goes;
      // otherwise it is halved, so that a rim leaving the solid and coming
      // back (two contacts a few degrees apart, as a tilted piston meets a
      // chamfered mouth) is not taken for one arc through the gap.
      if (level >= kMaxLevels ||
          Monotone(a.v.f, a.v.slope, b.v.f, b.v.slope, bounds.curvature, w) ||
          lines.OneCrossed(a.v, b.v, w)) {
        Add(Crossing(field, a, b));
        return;
      }
    } else {
      // f cannot leave its side and come back over the interval: by its
      // slope bound, or by its curvature bound (f stays within K w^2 / 8 of
      // the chord, w the interval's width, K >= |f''| on it: TravelBounds,
      // or within K t^2 / 2 of its tangents at the ends: TangentsKeepSide),
      // or because the trace can cross none of the edges near it (EdgeLines:
      // their lines have no kink where f has one, at a corner).
      if (CannotReachZero(std::abs(a.v.f), std::abs(b.v.f), bounds.slope,
                          bounds.curvature, w) ||
          TangentsKeepSide(a.v.f, a.v.slope, b.v.f, b.v.slope, bounds.curvature, w))
        return;
      if (lines.NoneCrossed(a.v, b.v, w)) return;
      if (level >= kMaxLevels) {
        // The finest interval. A dip into the solid narrower than it (a
        // rim crossing a corner's edge tilted 5 deg dips in a V 1 um deep
        // and 5e-4 rad wide) or a gap out of it, between ends whose slopes
        // bracket f's least (greatest), is found by the deepest point's
        // search (Extremum); another is shallower than the slope bound
        // over the interval, and left out.
        const double s = a.inside() ? -1.0 : 1.0;
        if (s * a.v.slope < 0 && s * b.v.slope > 0) {
          const Sample m = Extremum(field, a, b, s);
          if (m.inside() != a.inside()) {
            Add(Crossing(field, a, m));
            Add(Crossing(field, m, b));
          }
        }
        return;
      }
    }
    const double h = kScanAngles.half[level];
    const Unit um{(ua.cs + ub.cs) * h, (ua.sn + ub.sn) * h};
    const Sample m{0.5 * (a.phi + b.phi), field.At(um.cs, um.sn)};
    Interval(a, ua, m, um, level + 1);
    Interval(m, um, b, ub, level + 1);
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
  return {dr, dz, ddr, slope, curvature};
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

int InsideArcs(const PlacedCircle& c, const NearEdges& solid, Arc arcs[kMaxArcs],
               std::uint64_t* queries, std::uint64_t* edges, double margin) {
  if (solid.clear()) return 0;
  const CircleField field(c, solid, queries, edges, margin);
  Scan scan(field,
            TravelBounds(c, std::max(0.0, solid.box().r_min), solid.corner_distance()));
  const double step = 2 * M_PI / kSamples;
  const Unit* u = kScanAngles.sample;
  const Sample first{0.0, field.At(u[0].cs, u[0].sn)};
  Sample a = first;
  for (int k = 1; k <= kSamples; ++k) {
    const Sample b = k == kSamples ? Sample{2 * M_PI, first.v}
                                   : Sample{k * step, field.At(u[k].cs, u[k].sn)};
    scan.Interval(a, u[k - 1], b, u[k], 0);
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

double DeepestAngle(const PlacedCircle& c, const NearEdges& solid, const Arc& arc,
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
  const Sample a{lo, field(lo)};
  const Sample b{hi, field(hi)};
  // Where the slopes' chord crosses zero, rather than an end of the last
  // bracket, when the tolerance stops the search: in a flat-bottomed bowl
  // (a rim tilted in a bore) the bracket may then be wide, and which of its
  // ends is the lower can flip with a rounding of the pose, the
  // quadrature's nodes with it (in a trial the point moved 0.006 rad and
  // the load by 17 N of 56 N for 1e-11 m of travel). The chord's zero lies
  // between the ends, and moves with their slopes.
  double chord = std::numeric_limits<double>::quiet_NaN();
  const Sample least = Extremum(field, a, b, 1.0, &chord);
  return std::isnan(chord) ? least.phi : chord;
}

}  // namespace vahf::contact
