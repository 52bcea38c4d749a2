// The validated scene: parts, the operator, every model parameter and the
// assembly sequence. SI units (m, kg, s, N, rad in code, degrees in files);
// world frame z up. See docs/scene-format.md.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vahf/geometry/clearance.h"
#include "vahf/geometry/shape.h"
#include "vahf/human/operator_model.h"
#include "vahf/scene/parameters.h"

namespace vahf::scene {

enum class Role {
  kBase,        // fixed, the part everything is assembled onto
  kAssembling,  // moved by the operator, in the order of the sequence
  kAssembled,   // already in place: fixed at its target pose
};

const char* RoleName(Role role);

// A part frame's pose in the world: position of its origin, and orientation as
// body-fixed X-Y-Z rotations (Simbody's BodyRotationSequence XYZ), degrees.
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_xyz_deg = Eigen::Vector3d::Zero();

  Eigen::Matrix3d Rotation() const {
    const Eigen::Vector3d a = rotation_xyz_deg * (M_PI / 180.0);
    return (Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()) *
            Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()))
        .toRotationMatrix();
  }
  Eigen::Isometry3d Transform() const {
    Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
    x.linear() = Rotation();
    x.translation() = position;
    return x;
  }
};

struct Part {
  std::string name;
  Role role = Role::kBase;
  geometry::Shape shape;
  geometry::MassProperties mass_properties;  // computed from shape
  double mass = 0.0;                         // kg: given, or density * volume
  double density = 0.0;                      // kg/m^3: given, or mass / volume
  double friction = 0.0;                     // Coulomb coefficient, dimensionless
  Pose initial;  // for base and assembled parts: where they are
  Pose target;   // the assembled pose (T_t); equals initial when fixed
  // Where the operator's hand applies the assembly force, part frame, m
  // (default: the centroid).
  Eigen::Vector3d grasp = Eigen::Vector3d::Zero();
};

// Standard gravity, m/s^2 (ISO 80000-3).
inline constexpr double kStandardGravity = 9.80665;

struct Scene {
  std::string file;  // where it was read from, for messages
  std::string name;
  std::string description;
  Eigen::Vector3d gravity{0.0, 0.0, -kStandardGravity};  // m/s^2
  human::Operator op;
  std::vector<Part> parts;
  std::vector<int> sequence;  // indices into parts, in assembly order
  Parameters params;
};

// A part that stays where it is while the part at `position` of the
// sequence is assembled: the base, parts with role "assembled", and the parts
// assembled earlier in the sequence (at their targets). Later parts are not
// in that trial at all.
struct FixedPart {
  const Part* part;
  Eigen::Isometry3d pose;
};
std::vector<FixedPart> FixedPartsAt(const Scene& scene, std::size_t position);

// The tightest radial fit (geometry::SmallestRadialFit) of `part` at its
// target with one of `fixed`, and that part; none when no fixed part fits it.
struct TightFit {
  geometry::RadialFit fit;
  const Part* with = nullptr;
};
std::optional<TightFit> TightestFit(const Part& part,
                                    const std::vector<FixedPart>& fixed);

}  // namespace vahf::scene
