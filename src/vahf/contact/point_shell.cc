#include "vahf/contact/point_shell.h"

#include <algorithm>
#include <cmath>

namespace vahf::contact {
namespace {

int Divisions(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

void RevolutionShell(const geometry::RevolvedProfile& p, double spacing,
                     std::vector<ShellPoint>* out) {
  const auto& v = p.vertices;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const geometry::ProfilePoint a = v[k], b = v[(k + 1) % v.size()];
    if (a.r == 0.0 && b.r == 0.0) continue;  // on the axis: not surface
    const double dr = b.r - a.r, dz = b.z - a.z;
    const double slant = std::hypot(dr, dz);
    // Counter-clockwise profile: outward normal is the edge direction turned clockwise.
    const double nr = dz / slant, nz = -dr / slant;
    const int along = Divisions(slant, spacing);
    for (int i = 0; i < along; ++i) {
      const double t = (i + 0.5) / along;
      const double r = a.r + t * dr, z = a.z + t * dz;
      const int around = Divisions(2 * M_PI * r, spacing);
      const double band = 2 * M_PI * r * slant / along;  // exact band area
      for (int j = 0; j < around; ++j) {
        const double phi = 2 * M_PI * (j + 0.5) / around;
        const double c = std::cos(phi), s = std::sin(phi);
        out->push_back({{r * c, r * s, z}, {nr * c, nr * s, nz}, band / around});
      }
    }
  }
}

void BoxShell(const geometry::Box& box, double spacing, std::vector<ShellPoint>* out) {
  const Eigen::Vector3d h = 0.5 * box.size;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    const int nu = Divisions(box.size[u], spacing), nw = Divisions(box.size[w], spacing);
    const double area = box.size[u] * box.size[w] / (nu * nw);
    for (double side : {-1.0, 1.0}) {
      for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nw; ++j) {
          Eigen::Vector3d p, n = Eigen::Vector3d::Zero();
          p[axis] = side * h[axis];
          p[u] = -h[u] + (i + 0.5) * box.size[u] / nu;
          p[w] = -h[w] + (j + 0.5) * box.size[w] / nw;
          n[axis] = side;
          out->push_back({p, n, area});
        }
      }
    }
  }
}

// Divisions() in double: the count of a length that may not fit an int.
double DivisionsBound(double length, double spacing) {
  return std::max(1.0, std::ceil(length / spacing));
}

}  // namespace

double PointShellSizeBound(const geometry::Shape& shape, double spacing) {
  double n = 0;
  if (const auto* p = std::get_if<geometry::RevolvedProfile>(&shape)) {
    const auto& v = p->vertices;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const geometry::ProfilePoint a = v[k], b = v[(k + 1) % v.size()];
      if (a.r == 0.0 && b.r == 0.0) continue;
      // Band i's ring has ceil(2 pi r_i / s) <= 2 pi r_i / s + 1 points, and
      // the band radii r_i average (a.r + b.r) / 2 over the edge.
      n += DivisionsBound(std::hypot(b.r - a.r, b.z - a.z), spacing) *
           (1 + M_PI * (a.r + b.r) / spacing);
    }
    return n;
  }
  const Eigen::Vector3d& size = std::get<geometry::Box>(shape).size;
  for (int axis = 0; axis < 3; ++axis)
    n += 2 * DivisionsBound(size[(axis + 1) % 3], spacing) *
         DivisionsBound(size[(axis + 2) % 3], spacing);
  return n;
}

std::vector<ShellPoint> MakePointShell(const geometry::Shape& shape, double spacing) {
  std::vector<ShellPoint> out;
  if (const auto* p = std::get_if<geometry::RevolvedProfile>(&shape))
    RevolutionShell(*p, spacing, &out);
  else
    BoxShell(std::get<geometry::Box>(shape), spacing, &out);
  return out;
}

}  // namespace vahf::contact
