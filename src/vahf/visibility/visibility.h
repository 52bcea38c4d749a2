// Visibility V of the assembling part by ray casting (Sec. 3.2.1, Eq. 1):
// V = V_a / V_b, V_b the pixels of the part with only the part shown, V_a the
// pixels where the part is the nearest thing seen with every fixed part shown.
//
// The "camera" sits at the operator's eye and looks at the centre c of the
// part's bounding sphere (radius R, distance d = |c - eye|): a pinhole view
// whose square image just holds the sphere, half-angle asin(R / d), N x N
// pixels evenly spaced on the tangent plane at unit distance; one ray through
// each pixel centre. docs/visibility.md has the method and its error.
//
// Built once (Embree device, meshes, BVHs); the moving part is an Embree
// instance, so a new pose costs a transform and a top-level commit, never a
// re-tessellation. Single-threaded and deterministic: the same inputs give
// the same bits, whatever the caster computed before. Not safe to share
// between threads (Compute moves the instance): caster_pool.h lends one
// caster to one user at a time.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <vector>

#include "vahf/geometry/tessellation.h"
#include "vahf/visibility/visibility_params.h"

namespace vahf::visibility {

// A fixed part that may hide the assembling one: its mesh in its own frame
// and its pose X_WO in the world.
struct Occluder {
  geometry::TriangleMesh mesh;
  Eigen::Isometry3d X_WO = Eigen::Isometry3d::Identity();
};

// How a Compute obtained V.
enum class VisibilityPath {
  // Pixels counted by casting rays.
  kRaysCast,
  // No occluder's bounding sphere reaches the view cone in front of the part,
  // so nothing can hide it: V_a = V_b, V = 1 by Eq. 1, no ray cast.
  kNothingCanHide,
  // The eye is inside the part's bounding sphere (d <= R): no view can hold the
  // part, nothing of it is imaged, V_b = 0 and V = 0 (the rule of
  // human::Visibility), no ray cast.
  kEyeInsideBoundingSphere,
};

const char* VisibilityPathName(VisibilityPath path);

struct VisibilityResult {
  std::int64_t part_pixels = 0;     // V_b (0 when no ray was cast)
  std::int64_t visible_pixels = 0;  // V_a (0 when no ray was cast)
  double V = 0.0;                   // Eq. 1, in [0, 1]
  std::int64_t rays_cast = 0;       // Embree ray queries, both passes
  VisibilityPath path = VisibilityPath::kRaysCast;
};

struct CasterOptions {
  int grid = 128;  // N of the N x N ray grid, 1..kMaxGrid
  // Cast both passes of Eq. 1 in full: every pixel once with everything shown
  // and once with the part alone. Off (the default), V_b and V_a come from one
  // traversal: a pixel whose nearest hit is the part counts in both; only a
  // pixel whose nearest hit is an occluder is cast again at the part alone;
  // a pixel whose ray misses the part's bounding sphere is not cast. The
  // counts are identical either way (tests/visibility/visibility_test.cc).
  bool two_pass = false;
};

class VisibilityCaster {
 public:
  // part_mesh_P: the assembling part in its own frame P; occluders: the fixed
  // parts. Throws vahf::InputError for a grid out of range or a part mesh
  // without triangles, ComputationError (kRefused) if Embree cannot build its scenes.
  VisibilityCaster(const geometry::TriangleMesh& part_mesh_P,
                   const std::vector<Occluder>& occluders, CasterOptions options = {});
  ~VisibilityCaster();
  VisibilityCaster(VisibilityCaster&&) noexcept;
  VisibilityCaster& operator=(VisibilityCaster&&) noexcept;
  VisibilityCaster(const VisibilityCaster&) = delete;
  VisibilityCaster& operator=(const VisibilityCaster&) = delete;

  // Eq. 1 for the part at pose X_WP seen from p_W_eye (world, m). Throws
  // vahf::InputError when either is not finite.
  VisibilityResult Compute(const Eigen::Vector3d& p_W_eye, const Eigen::Isometry3d& X_WP);

  // The part's bounding sphere in its own frame: centre (m) and radius (m).
  const Eigen::Vector3d& part_bounding_centre() const;
  double part_bounding_radius() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vahf::visibility
