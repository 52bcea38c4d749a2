#include "vahf/contact/rim.h"

#include <algorithm>
#include <cmath>

namespace vahf::contact {
namespace {

int Samples(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

void RevolutionRims(const geometry::RevolvedProfile& p, double spacing,
                    std::vector<RimPoint>* out) {
  for (const RimCircle& rim : RimCircles(p)) {
    const double circumference = 2 * M_PI * rim.radius;
    const int count = Samples(circumference, spacing);
    const double length = circumference / count;
    for (int j = 0; j < count; ++j) {
      const double phi = 2 * M_PI * (j + 0.5) / count;
      out->push_back(
          {{rim.radius * std::cos(phi), rim.radius * std::sin(phi), rim.height}, length});
    }
  }
}

void BoxRims(const geometry::Box& box, double spacing, std::vector<RimPoint>* out) {
  const Eigen::Vector3d h = 0.5 * box.size;
  for (int axis = 0; axis < 3; ++axis) {  // edges along `axis`
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    const double edge = box.size[axis];
    const int count = Samples(edge, spacing);
    const double length = edge / count;
    for (double su : {-1.0, 1.0}) {
      for (double sw : {-1.0, 1.0}) {
        for (int i = 0; i < count; ++i) {
          Eigen::Vector3d p;
          p[axis] = -h[axis] + (i + 0.5) * length;
          p[u] = su * h[u];
          p[w] = sw * h[w];
          out->push_back({p, length});
        }
      }
    }
  }
}

}  // namespace

std::vector<RimCircle> RimCircles(const geometry::RevolvedProfile& p) {
  const auto& v = p.vertices;
  const std::size_t n = v.size();
  std::vector<RimCircle> out;
  for (std::size_t k = 0; k < n; ++k) {
    const geometry::ProfilePoint a = v[(k + n - 1) % n], b = v[k], c = v[(k + 1) % n];
    if (!(b.r > 0)) continue;  // on the axis: no circle
    // Turn from the incoming to the outgoing edge: positive (left) is convex
    // for a counter-clockwise polygon; the interior angle is pi minus it.
    const double in_r = b.r - a.r, in_z = b.z - a.z;
    const double out_r = c.r - b.r, out_z = c.z - b.z;
    const double turn =
        std::atan2(in_r * out_z - in_z * out_r, in_r * out_r + in_z * out_z);
    if (turn > kMinRimTurnRad) out.push_back({b.r, b.z});
  }
  return out;
}

double RimSizeBound(const geometry::Shape& shape, double spacing) {
  const auto count = [&](double length) {
    return std::max(1.0, std::ceil(length / spacing));
  };
  double n = 0;
  if (const auto* p = std::get_if<geometry::RevolvedProfile>(&shape)) {
    for (const geometry::ProfilePoint& v : p->vertices)
      if (v.r > 0)
        n += count(2 * M_PI * v.r);  // every vertex off the axis, convex or not
    return n;
  }
  const Eigen::Vector3d& size = std::get<geometry::Box>(shape).size;
  for (int axis = 0; axis < 3; ++axis) n += 4 * count(size[axis]);
  return n;
}

std::vector<RimPoint> MakeRims(const geometry::Shape& shape, double spacing) {
  std::vector<RimPoint> out;
  if (const auto* p = std::get_if<geometry::RevolvedProfile>(&shape))
    RevolutionRims(*p, spacing, &out);
  else
    BoxRims(std::get<geometry::Box>(shape), spacing, &out);
  return out;
}

}  // namespace vahf::contact
