#include "vahf/visibility/visibility.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "vahf/core/error.h"
#include "vahf/geometry/bounding_sphere.h"
#include "vahf/human/factors.h"

namespace vahf::visibility {
namespace {

// Embree picks its kernels by the CPU it runs on (SSE2 ... AVX-512, with or
// without FMA), so a hit decision near an edge could differ between machines.
// Pinned to the baseline SSE2 kernels, like the rest of vahf is built for
// baseline x86-64 (docs/design.md decision 9): the same instructions everywhere.
// One thread: BVH builds and queries run in the caller's thread.
#if defined(__x86_64__) || defined(_M_X64)
constexpr const char* kDeviceConfig = "threads=1,isa=sse2";
#else
constexpr const char* kDeviceConfig = "threads=1";
#endif

// Rays through pixels whose tangent-plane offset exceeds tan(alpha) by this
// relative margin (of tan^2) cannot reach the part's bounding sphere; the
// margin covers rounding to float. An occluder is out of the view when its
// angular gap to the view cone exceeds kAngleMargin (rad).
constexpr double kConeMargin = 1e-5;
constexpr double kAngleMargin = 1e-6;
constexpr float kInf = std::numeric_limits<float>::infinity();

struct Sphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

// A sphere holding every vertex (geometry/bounding_sphere.h).
Sphere BoundingSphere(const std::vector<Eigen::Vector3d>& points) {
  const geometry::BoundingSphere b = geometry::BoundPoints(
      points.begin(), points.end(), [](const Eigen::Vector3d& p) { return p; });
  return {b.centre, b.radius};
}

// Could `occluder` hide any point of the part's bounding sphere (distance d
// from the eye along unit axis `a`, radius R, half-angle alpha)? A hiding
// point lies on a segment from the eye to a part point: inside the view cone
// and nearer than d + R. Conservative: true unless surely outside that region.
bool MayHide(const Sphere& occluder, const Eigen::Vector3d& eye, const Eigen::Vector3d& a,
             double d, double R, double alpha) {
  const Eigen::Vector3d v = occluder.centre - eye;
  const double l = v.norm();
  if (l <= occluder.radius) return true;           // the eye is inside it
  if (l - occluder.radius >= d + R) return false;  // wholly beyond the part
  const double theta = std::acos(std::clamp(v.dot(a) / l, -1.0, 1.0));
  const double beta = std::asin(occluder.radius / l);  // its angular radius
  return theta - beta - alpha <= kAngleMargin;
}

// An orthonormal pair across unit axis a, from the world axis least aligned
// with it (a fixed rule: the same a always gives the same pixels).
void ImageAxes(const Eigen::Vector3d& a, Eigen::Vector3d* e1, Eigen::Vector3d* e2) {
  Eigen::Index k = 0;
  a.cwiseAbs().minCoeff(&k);
  *e1 = a.cross(Eigen::Vector3d::Unit(k)).normalized();
  *e2 = a.cross(*e1);
}

void Check(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE)
    throw ComputationError(
        ComputationError::Reason::kRefused,
        fmt::format("Embree failed to {} (error {})", what, static_cast<int>(e)));
}

// A static scene of triangle meshes (vertices given apart from the meshes, as
// the occluders' are moved to the world first), robust traversal, built once.
RTCScene MeshScene(RTCDevice device,
                   const std::vector<const std::vector<Eigen::Vector3d>*>& vertex_sets,
                   const std::vector<const geometry::TriangleMesh*>& meshes) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const auto& vertices = *vertex_sets[m];
    const auto& triangles = meshes[m]->triangles;
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), vertices.size()));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), triangles.size()));
    Check(device, "allocate a mesh");
    for (std::size_t i = 0; i < vertices.size(); ++i)
      for (int c = 0; c < 3; ++c) vb[3 * i + c] = static_cast<float>(vertices[i][c]);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      for (int c = 0; c < 3; ++c) {
        const std::int32_t index = triangles[t][c];
        VAHF_CHECK(index >= 0 && static_cast<std::size_t>(index) < vertices.size(),
                   "triangle indices address the mesh's vertices");
        ib[3 * t + c] = static_cast<unsigned>(index);
      }
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(scene);
  Check(device, "build a mesh BVH");
  return scene;
}

// Attaches an instance of `of` to `top`; the caller owns the returned handle.
RTCGeometry AttachInstance(RTCDevice device, RTCScene top, RTCScene of) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(g, of);
  const float identity[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, identity);
  rtcCommitGeometry(g);
  rtcAttachGeometry(top, g);
  return g;
}

RTCScene NewTopScene(RTCDevice device) {
  RTCScene top = rtcNewScene(device);
  rtcSetSceneFlags(top, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(top, RTC_BUILD_QUALITY_LOW);  // one or two instances
  return top;
}

void SetRay(RTCRay4* r, int k, const Eigen::Vector3f& origin, const Eigen::Vector3f& dir,
            float tfar) {
  r->org_x[k] = origin.x();
  r->org_y[k] = origin.y();
  r->org_z[k] = origin.z();
  r->tnear[k] = 0.0f;
  r->dir_x[k] = dir.x();
  r->dir_y[k] = dir.y();
  r->dir_z[k] = dir.z();
  r->time[k] = 0.0f;
  r->tfar[k] = tfar;
  r->mask[k] = ~0u;
  r->id[k] = 0;
  r->flags[k] = 0;
}

RTCRayHit Ray(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir) {
  RTCRayHit r;
  r.ray.org_x = origin.x();
  r.ray.org_y = origin.y();
  r.ray.org_z = origin.z();
  r.ray.tnear = 0.0f;
  r.ray.dir_x = dir.x();
  r.ray.dir_y = dir.y();
  r.ray.dir_z = dir.z();
  r.ray.time = 0.0f;
  r.ray.tfar = kInf;
  r.ray.mask = ~0u;
  r.ray.id = 0;
  r.ray.flags = 0;
  r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return r;
}

// The single-traversal form of Eq. 1, in packets of 4 rays (native on every
// x86-64 Embree kernel): the part alone first (V_b); for each ray that hits
// it, whether any occluder lies before that hit (if none: V_a). An occluder
// exactly as far as the part counts as hiding it.
class PacketCaster {
 public:
  PacketCaster(RTCScene part_alone, RTCScene occluders, const Eigen::Vector3f& origin,
               VisibilityResult* result)
      : part_alone_(part_alone), occluders_(occluders), origin_(origin), result_(result) {
    rtcInitIntersectContext(&context_);
    context_.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  }

  void Add(const Eigen::Vector3f& direction) {
    SetRay(&alone_.ray, n_alone_, origin_, direction, kInf);
    alone_.hit.geomID[n_alone_] = RTC_INVALID_GEOMETRY_ID;
    alone_.hit.instID[0][n_alone_] = RTC_INVALID_GEOMETRY_ID;
    if (++n_alone_ == kWidth) FlushAlone();
  }
  void Finish() {
    FlushAlone();
    FlushBefore();
  }

 private:
  static constexpr int kWidth = 4;
  using Valid = std::array<int, kWidth>;  // Embree's lane mask: -1 active, 0 not

  static Valid FirstLanes(int count) {
    Valid valid;
    for (int k = 0; k < kWidth; ++k) valid[k] = k < count ? -1 : 0;
    return valid;
  }

  void FlushAlone() {
    if (n_alone_ == 0) return;
    const Valid valid = FirstLanes(n_alone_);
    rtcIntersect4(valid.data(), part_alone_, &context_, &alone_);
    result_->rays_cast += n_alone_;
    for (int k = 0; k < n_alone_; ++k) {
      if (alone_.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) continue;
      ++result_->part_pixels;
      const Eigen::Vector3f dir(alone_.ray.dir_x[k], alone_.ray.dir_y[k],
                                alone_.ray.dir_z[k]);
      SetRay(&before_, n_before_, origin_, dir, alone_.ray.tfar[k]);
      if (++n_before_ == kWidth) FlushBefore();
    }
    n_alone_ = 0;
  }
  void FlushBefore() {
    if (n_before_ == 0) return;
    const Valid valid = FirstLanes(n_before_);
    rtcOccluded4(valid.data(), occluders_, &context_, &before_);
    result_->rays_cast += n_before_;
    for (int k = 0; k < n_before_; ++k)
      if (before_.tfar[k] != -kInf) ++result_->visible_pixels;  // Embree: -inf if hit
    n_before_ = 0;
  }

  RTCScene part_alone_, occluders_;
  Eigen::Vector3f origin_;
  VisibilityResult* result_;
  RTCIntersectContext context_;
  RTCRayHit4 alone_;
  RTCRay4 before_;
  int n_alone_ = 0, n_before_ = 0;
};

}  // namespace

const char* VisibilityPathName(VisibilityPath path) {
  switch (path) {
    case VisibilityPath::kRaysCast:
      return "rays_cast";
    case VisibilityPath::kNothingCanHide:
      return "nothing_can_hide";
    case VisibilityPath::kEyeInsideBoundingSphere:
      return "eye_inside_bounding_sphere";
  }
  return "?";
}

struct VisibilityCaster::Impl {
  CasterOptions options;
  Sphere part_P;                    // the part's bounding sphere, part frame
  std::vector<Sphere> occluders_W;  // one per occluder with triangles, world
  RTCDevice device = nullptr;
  RTCScene part_scene = nullptr;      // the part's mesh, part frame
  RTCScene occluder_scene = nullptr;  // every occluder, world frame; null if none
  // The part placed by an instance: alone, and (two_pass only) with the
  // occluders, its instance id then kPartInstance.
  RTCScene part_alone = nullptr, everything = nullptr;
  std::vector<RTCGeometry> part_instances;
  std::array<float, 12> committed_X_WP{};  // the transform Embree holds
  bool committed = false;
  static constexpr unsigned kPartInstance = 0;

  ~Impl() {
    for (RTCGeometry g : part_instances) rtcReleaseGeometry(g);
    for (RTCScene s : {everything, part_alone, occluder_scene, part_scene})
      if (s) rtcReleaseScene(s);
    if (device) rtcReleaseDevice(device);
  }

  // Moves the part's instances to X_WP and commits their top levels (one or
  // two instances: cheap); nothing when the pose has not changed. The only
  // state a Compute changes: what it leaves depends on X_WP alone, so a caster
  // gives the same bits whatever it cast before (caster_pool.h). A commit
  // that throws leaves nothing committed, and the next Place commits again.
  void Place(const Eigen::Isometry3d& X_WP) {
    std::array<float, 12> x;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) x[3 * c + r] = static_cast<float>(X_WP.linear()(r, c));
    for (int r = 0; r < 3; ++r) x[9 + r] = static_cast<float>(X_WP.translation()(r));
    if (committed && x == committed_X_WP) return;
    committed = false;
    for (RTCGeometry g : part_instances) {
      rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, x.data());
      rtcCommitGeometry(g);
    }
    rtcCommitScene(part_alone);
    if (everything) rtcCommitScene(everything);
    Check(device, "commit the moved part");
    committed_X_WP = x;
    committed = true;
  }

  // One pixel of Eq. 1, literally: the nearest hit with everything shown is
  // the part (V_a); the ray hits the part with only the part shown (V_b).
  void CastTwoPasses(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
                     RTCIntersectContext* context, VisibilityResult* result) const {
    RTCRayHit all = Ray(origin, direction);
    rtcIntersect1(everything, context, &all);
    RTCRayHit alone = Ray(origin, direction);
    rtcIntersect1(part_alone, context, &alone);
    result->rays_cast += 2;
    if (all.hit.geomID != RTC_INVALID_GEOMETRY_ID && all.hit.instID[0] == kPartInstance)
      ++result->visible_pixels;
    if (alone.hit.geomID != RTC_INVALID_GEOMETRY_ID) ++result->part_pixels;
  }
};

VisibilityCaster::VisibilityCaster(const geometry::TriangleMesh& part_mesh_P,
                                   const std::vector<Occluder>& occluders,
                                   CasterOptions options)
    : impl_(std::make_unique<Impl>()) {
  if (options.grid < 1 || options.grid > kMaxGrid)
    throw InputError("", "visibility grid", std::to_string(options.grid),
                     fmt::format("must be an integer from 1 to {}", kMaxGrid));
  if (part_mesh_P.triangles.empty() || part_mesh_P.vertices.empty())
    throw InputError("", "assembling part mesh", "no triangles",
                     "the part to be seen needs a surface");
  Impl& s = *impl_;
  s.options = options;
  s.part_P = BoundingSphere(part_mesh_P.vertices);

  s.device = rtcNewDevice(kDeviceConfig);
  if (!s.device)
    throw ComputationError(ComputationError::Reason::kRefused,
                           fmt::format("Embree cannot create a device (error {})",
                                       static_cast<int>(rtcGetDeviceError(nullptr))));
  s.part_scene = MeshScene(s.device, {&part_mesh_P.vertices}, {&part_mesh_P});

  // Occluders are fixed: their vertices go into the world frame once.
  std::vector<std::vector<Eigen::Vector3d>> world;
  std::vector<const geometry::TriangleMesh*> meshes;
  for (const Occluder& o : occluders) {
    if (o.mesh.triangles.empty()) continue;
    world.emplace_back();
    for (const Eigen::Vector3d& p : o.mesh.vertices) world.back().push_back(o.X_WO * p);
    meshes.push_back(&o.mesh);
    s.occluders_W.push_back(BoundingSphere(world.back()));
  }
  if (!meshes.empty()) {
    std::vector<const std::vector<Eigen::Vector3d>*> vertex_sets;
    for (const auto& w : world) vertex_sets.push_back(&w);
    s.occluder_scene = MeshScene(s.device, vertex_sets, meshes);
  }
  s.part_alone = NewTopScene(s.device);
  s.part_instances.push_back(AttachInstance(s.device, s.part_alone, s.part_scene));
  if (options.two_pass && s.occluder_scene) {
    s.everything = NewTopScene(s.device);
    s.part_instances.push_back(AttachInstance(s.device, s.everything, s.part_scene));
    rtcReleaseGeometry(AttachInstance(s.device, s.everything, s.occluder_scene));
  }
  Check(s.device, "set up the instances");
}

VisibilityCaster::~VisibilityCaster() = default;
VisibilityCaster::VisibilityCaster(VisibilityCaster&&) noexcept = default;
VisibilityCaster& VisibilityCaster::operator=(VisibilityCaster&&) noexcept = default;

const Eigen::Vector3d& VisibilityCaster::part_bounding_centre() const {
  return impl_->part_P.centre;
}
double VisibilityCaster::part_bounding_radius() const { return impl_->part_P.radius; }

VisibilityResult VisibilityCaster::Compute(const Eigen::Vector3d& p_W_eye,
                                           const Eigen::Isometry3d& X_WP) {
  if (!p_W_eye.allFinite())
    throw InputError("", "eye position", fmt::format("[{}]", fmt::join(p_W_eye, ", ")),
                     "must be finite");
  if (!X_WP.matrix().allFinite())
    throw InputError("", "part pose", "not finite", "must be a finite rigid transform");
  Impl& s = *impl_;
  VisibilityResult result;
  const Eigen::Vector3d c = X_WP * s.part_P.centre;
  const double R = s.part_P.radius;
  const double d = (c - p_W_eye).norm();
  if (d <= R) {
    result.path = VisibilityPath::kEyeInsideBoundingSphere;
    result.V = human::Visibility(0, 0);
    return result;
  }
  const Eigen::Vector3d a = (c - p_W_eye) / d;  // the view axis
  const double alpha = std::asin(R / d);
  // Eq. 1 with no possible obstacle: V_a = V_b, so V = 1 without a ray.
  const bool may_hide =
      std::any_of(s.occluders_W.begin(), s.occluders_W.end(),
                  [&](const Sphere& o) { return MayHide(o, p_W_eye, a, d, R, alpha); });
  if (!may_hide) {
    result.path = VisibilityPath::kNothingCanHide;
    result.V = 1.0;
    return result;
  }
  VAHF_CHECK(s.occluder_scene, "an occluder that may hide the part has a scene");

  // Pixel (i, j) is the ray through a + u e1 + v e2 on the tangent plane at
  // unit distance, u and v evenly spaced pixel centres in [-tan(alpha), tan(alpha)].
  s.Place(X_WP);
  Eigen::Vector3d e1, e2;
  ImageAxes(a, &e1, &e2);
  const int n = s.options.grid;
  const double tan_alpha = R / std::sqrt((d - R) * (d + R));
  const double cone = tan_alpha * tan_alpha * (1.0 + kConeMargin);  // on u^2 + v^2
  const Eigen::Vector3f origin = p_W_eye.cast<float>();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  PacketCaster packets(s.part_alone, s.occluder_scene, origin, &result);
  for (int i = 0; i < n; ++i) {
    const double v = ((2.0 * i + 1.0) / n - 1.0) * tan_alpha;
    for (int j = 0; j < n; ++j) {
      const double u = ((2.0 * j + 1.0) / n - 1.0) * tan_alpha;
      const Eigen::Vector3f direction = (a + u * e1 + v * e2).cast<float>();
      if (s.options.two_pass) {
        s.CastTwoPasses(origin, direction, &context, &result);
      } else if (u * u + v * v <= cone) {  // else it misses the bounding sphere
        packets.Add(direction);
      }
    }
  }
  packets.Finish();
  Check(s.device, "cast rays");
  result.V = human::Visibility(result.visible_pixels, result.part_pixels);  // Eq. 1
  return result;
}

}  // namespace vahf::visibility
