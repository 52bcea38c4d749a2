// Speed of the visibility V of Eq. 1 by ray casting in the peg scene
// (experiments/scenes/peg_in_hole.json): the peg 20 mm above its target, so
// the bore hides its lower part, seen from the standing operator's eye.
// - PegV/N: one V on an N x N grid (the target is under 1 ms at N = 128 on one
//   core). Each iteration moves the peg by 1 micrometre and back, so every V
//   pays the instance move and top-level commit a trial would pay.
// - PegTessellation, PegCasterSetUp: the one-time cost per part and
//   experiment (and per thread for the caster), split into meshing both parts
//   and building the caster (Embree device, BVHs); MinimalCasterSetUp: a
//   caster with almost nothing in it (the device); PegCasterBorrow: what a
//   trial pays for its caster instead, a borrow from and return to the trial
//   model's pool (visibility/caster_pool.h).
// Run with tools/bench, or taskset -c 0 build/release/bench/visibility_benchmark.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "vahf/geometry/tessellation.h"
#include "vahf/human/operator_model.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/visibility/caster_pool.h"
#include "vahf/visibility/visibility.h"

namespace {

using vahf::visibility::Occluder;

struct PegScene {
  vahf::scene::Scene scene;
  const vahf::scene::Part* peg = nullptr;
  std::vector<const vahf::scene::Part*> fixed;
  Eigen::Vector3d eye;
  Eigen::Isometry3d X_WP;  // the peg 20 mm above its target
  double tolerance = 0.0;

  PegScene()
      : scene(vahf::scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                     "/experiments/scenes/peg_in_hole.json")) {
    peg = &scene.parts[scene.sequence.front()];
    for (const auto& p : scene.parts)
      if (p.role != vahf::scene::Role::kAssembling) fixed.push_back(&p);
    eye = vahf::human::StandingPosture(scene.op).eye;
    X_WP = peg->target.Transform();
    X_WP.translation().z() += 0.020;
    tolerance = scene.params.visibility.tessellation_tolerance;
  }

  std::vector<Occluder> Occluders() const {
    std::vector<Occluder> out;
    for (const auto* p : fixed)
      out.push_back(
          {vahf::geometry::Tessellate(p->shape, tolerance), p->initial.Transform()});
    return out;
  }
};

void PegV(benchmark::State& state) {
  const PegScene s;
  vahf::visibility::VisibilityCaster caster(
      vahf::geometry::Tessellate(s.peg->shape, s.tolerance), s.Occluders(),
      {static_cast<int>(state.range(0)), false});
  Eigen::Isometry3d nudged = s.X_WP;
  nudged.translation().z() += 1e-6;
  std::int64_t rays = 0, k = 0;
  vahf::visibility::VisibilityResult r;
  for (auto _ : state) {
    r = caster.Compute(s.eye, (k++ % 2) ? nudged : s.X_WP);
    rays += r.rays_cast;
    // Not DoNotOptimize(r.V): with Debian's GCC 12 and Benchmark 1.7.1 its
    // "+r,m" asm constraint on a double lvalue clobbered the value here.
    benchmark::DoNotOptimize(r.part_pixels);
  }
  state.counters["V"] = r.V;
  state.counters["V_b"] = static_cast<double>(r.part_pixels);
  state.counters["rays"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kAvgIterations);
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(PegV)->RangeMultiplier(2)->Range(32, 512)->Unit(benchmark::kMicrosecond);

void PegTessellation(benchmark::State& state) {
  const PegScene s;
  std::size_t triangles = 0;
  for (auto _ : state) {
    triangles = vahf::geometry::Tessellate(s.peg->shape, s.tolerance).triangles.size();
    for (const auto& o : s.Occluders()) triangles += o.mesh.triangles.size();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(PegTessellation)->Unit(benchmark::kMicrosecond);

void PegCasterSetUp(benchmark::State& state) {
  const PegScene s;
  const vahf::geometry::TriangleMesh peg =
      vahf::geometry::Tessellate(s.peg->shape, s.tolerance);
  const std::vector<Occluder> occluders = s.Occluders();
  for (auto _ : state) {
    vahf::visibility::VisibilityCaster caster(peg, occluders, {128, false});
    benchmark::DoNotOptimize(caster.part_bounding_radius());
  }
}
BENCHMARK(PegCasterSetUp)->Unit(benchmark::kMicrosecond);

void PegCasterBorrow(benchmark::State& state) {
  const PegScene s;
  const vahf::visibility::CasterPool pool(
      vahf::geometry::Tessellate(s.peg->shape, s.tolerance), s.Occluders(), {128, false});
  pool.Borrow();  // the one caster the pool builds, idle from here on
  for (auto _ : state) {
    const vahf::visibility::CasterPool::Lease lease = pool.Borrow();
    benchmark::DoNotOptimize(lease.caster().part_bounding_radius());
  }
  state.counters["built"] = static_cast<double>(pool.casters_built());
}
BENCHMARK(PegCasterBorrow)->Unit(benchmark::kMicrosecond);

// The floor of PegCasterSetUp: a caster for a 12-triangle box and nothing
// else, mostly the Embree device.
void MinimalCasterSetUp(benchmark::State& state) {
  const vahf::geometry::TriangleMesh box =
      vahf::geometry::Tessellate(vahf::geometry::Box{{0.01, 0.01, 0.01}}, 1e-4);
  for (auto _ : state) {
    vahf::visibility::VisibilityCaster caster(box, {}, {128, false});
    benchmark::DoNotOptimize(caster.part_bounding_radius());
  }
}
BENCHMARK(MinimalCasterSetUp)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
