// Part geometry: a solid of revolution about the part frame's z axis, given by
// a closed profile polygon in the (r, z) half-plane r >= 0 (rods, bores,
// chamfers, sleeves, rings), or a box centred on the part frame origin.
// Lengths in metres, in the part's own frame.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "vahf/core/error.h"

namespace vahf::geometry {

struct ProfilePoint {
  double r;  // radius, m, >= 0
  double z;  // along the axis of revolution, m
};

struct RevolvedProfile {
  // Vertices of a simple polygon, counter-clockwise in the (r, z) plane,
  // without repeating the first vertex at the end.
  std::vector<ProfilePoint> vertices;
};

struct Box {
  Eigen::Vector3d size;  // full edge lengths along x, y, z, m
};

using Shape = std::variant<RevolvedProfile, Box>;

// The sizes a part may have, m, so that its contact shell, rims and meshes
// stay countable and its area and inertia sums cannot overflow: assembled
// parts are millimetres to metres (the paper's cylinder is about 0.5 m).
inline constexpr double kMaxExtent = 10.0;  // |r|, |z| of a profile point; a box edge
inline constexpr double kMinBoxEdge = 1e-4;
// A profile encloses at least this area (a 10 um square), m^2: less, and the
// sign of its area, which orients it, is lost to rounding.
inline constexpr double kMinProfileArea = 1e-10;
// Profile vertices: the self-crossing test is quadratic in them (1000 take
// a few ms; the shipped profiles have under 30).
inline constexpr std::size_t kMaxProfileVertices = 1000;

// A profile that breaks a rule of MakeRevolvedProfile: an input error whose file
// and JSON pointer the reader adds. point() is the index K of the vertex in the
// list as given (where() reads "point K"), or empty for a rule about the whole
// profile (where() reads "profile"); rule() states the rule.
class ProfileError : public InputError {
 public:
  ProfileError(std::optional<std::size_t> point, std::string rule)
      : InputError("", point ? "point " + std::to_string(*point) : "profile", "",
                   std::move(rule)),
        point_(point) {}

  const std::optional<std::size_t>& point() const { return point_; }

 private:
  std::optional<std::size_t> point_;
};

// Checks a profile as written in a file: a list of points whose last equals its
// first (closed), at least three distinct vertices and at most
// kMaxProfileVertices, 0 <= r <= kMaxExtent and |z| <= kMaxExtent, no
// repeated consecutive points, no self-crossing or folding edge, an area of
// at least kMinProfileArea. On success returns the polygon without the closing repeat,
// oriented counter-clockwise; on failure throws ProfileError.
RevolvedProfile MakeRevolvedProfile(const std::vector<ProfilePoint>& closed_points);

// Mass properties of a uniform solid, in the part frame.
struct MassProperties {
  double volume = 0.0;                // m^3
  Eigen::Vector3d centroid{0, 0, 0};  // m
  // Inertia per unit density about the centroid, along the part axes
  // (principal for both shapes): m^5, multiply by density for kg m^2.
  Eigen::Vector3d inertia_per_density{0, 0, 0};
  double bounding_radius = 0.0;  // radius of a sphere about the part origin holding it, m
};

MassProperties ComputeMassProperties(const Shape& shape);

}  // namespace vahf::geometry
