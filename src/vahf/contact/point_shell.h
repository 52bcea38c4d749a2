// A point shell on the moving part's surface: points at the centres of surface
// patches, each with its patch area and outward normal, so that summing
// pressure * area over the shell integrates a pressure over the surface. The
// total area, and so the total contact stiffness of a face, does not depend on
// the spacing (docs/design.md decision 7).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "vahf/geometry/shape.h"

namespace vahf::contact {

struct ShellPoint {
  Eigen::Vector3d position;  // in the part frame, m
  Eigen::Vector3d normal;    // outward unit normal, part frame
  double area;               // m^2
};

// Patches of side at most about `spacing` (m). For a solid of revolution each
// surface edge of the profile is split along its length and around the axis;
// a patch's area is exact (a frustum band's area is its mid radius times the
// slant length times the angle). For a box each face is a grid.
std::vector<ShellPoint> MakePointShell(const geometry::Shape& shape, double spacing);

// The most points MakePointShell can make for `shape` at `spacing`, computed
// without making them (in double, so it cannot overflow): what the scene rule
// kMaxShellPoints is checked against before any allocation.
double PointShellSizeBound(const geometry::Shape& shape, double spacing);

// Every contact evaluation visits each shell point's broad phase: a trial's
// step costs grow with it. 1e6 points (56 MB) is fifty times the finest
// shipped shell; more is a spacing mistake, not a finer model.
inline constexpr double kMaxShellPoints = 1e6;

}  // namespace vahf::contact
