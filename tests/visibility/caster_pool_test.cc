// The caster pool (visibility/caster_pool.h) against a fresh caster per V,
// the way every trial built its own before: a caster lent again, after it
// cast at other poses, counts exactly the pixels a fresh one counts at each of
// several poses of the peg in its bore; and the pool builds a caster only
// when none is idle (one for any number of borrowers in turn, one per
// borrower at once, at most one per thread).
#include "vahf/visibility/caster_pool.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "vahf/human/operator_model.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::visibility {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

// The peg scene's meshes and eye, and poses of the peg from above the bore
// (rays cast, nothing hidden) to seated in it (mostly hidden), with a tilt.
struct Peg {
  scene::Scene scene = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                        "/experiments/scenes/peg_in_hole.json");
  geometry::TriangleMesh part_P;
  std::vector<Occluder> fixed;
  Vector3d eye;
  std::vector<Isometry3d> poses;

  Peg() {
    const scene::Part& peg = scene.parts[scene.sequence.front()];
    part_P = geometry::Tessellate(peg.shape, 1e-4);
    for (const scene::Part& p : scene.parts)
      if (p.role != scene::Role::kAssembling)
        fixed.push_back({geometry::Tessellate(p.shape, 1e-4), p.initial.Transform()});
    eye = human::StandingPosture(scene.op).eye;
    for (const double raised : {0.05, 0.03, 0.02, 0.01, 0.0}) {
      Isometry3d X_WP = peg.target.Transform();
      X_WP.translation().z() += raised;
      poses.push_back(X_WP);
    }
    Isometry3d tilted = poses[2];
    tilted.linear() =
        tilted.linear() * Eigen::AngleAxisd(0.02, Vector3d::UnitX()).toRotationMatrix();
    poses.push_back(tilted);
  }
};

void ExpectSameBits(const VisibilityResult& a, const VisibilityResult& b, int pose) {
  EXPECT_EQ(a.part_pixels, b.part_pixels) << "pose " << pose;
  EXPECT_EQ(a.visible_pixels, b.visible_pixels) << "pose " << pose;
  EXPECT_EQ(a.rays_cast, b.rays_cast) << "pose " << pose;
  EXPECT_EQ(a.path, b.path) << "pose " << pose;
  EXPECT_EQ(std::memcmp(&a.V, &b.V, sizeof(double)), 0) << "pose " << pose;
}

TEST(CasterPool, ALentCasterCountsWhatAFreshOneCounts) {
  const Peg peg;
  const CasterOptions options{64, false};
  std::vector<VisibilityResult> fresh;
  for (const Isometry3d& X_WP : peg.poses)
    fresh.push_back(
        VisibilityCaster(peg.part_P, peg.fixed, options).Compute(peg.eye, X_WP));
  // Some poses hidden in part, some not: the counts say something.
  EXPECT_EQ(fresh.front().V, 1.0);
  EXPECT_LT(fresh.back().V, 0.9);
  EXPECT_GT(fresh.back().part_pixels, 0);

  const CasterPool pool(peg.part_P, peg.fixed, options);
  const int n = static_cast<int>(peg.poses.size());
  // Lent three times, each time over the poses in another order (forwards,
  // backwards, each pose twice in a row), so every pose follows a different one.
  for (int round = 0; round < 3; ++round) {
    const CasterPool::Lease lease = pool.Borrow();
    for (int k = 0; k < n; ++k) {
      const int pose = round == 1 ? n - 1 - k : k;
      for (int repeat = 0; repeat < (round == 2 ? 2 : 1); ++repeat)
        ExpectSameBits(lease.caster().Compute(peg.eye, peg.poses[pose]), fresh[pose],
                       pose);
    }
  }
  EXPECT_EQ(pool.casters_built(), 1u);
}

TEST(CasterPool, BuildsOnlyWhenNoCasterIsIdle) {
  const Peg peg;
  const CasterPool pool(peg.part_P, peg.fixed, {16, false});
  EXPECT_EQ(pool.casters_built(), 0u);  // nothing until first needed
  for (int k = 0; k < 5; ++k) {
    const CasterPool::Lease lease = pool.Borrow();
    lease.caster().Compute(peg.eye, peg.poses[k % peg.poses.size()]);
  }
  EXPECT_EQ(pool.casters_built(), 1u);
  {
    const CasterPool::Lease a = pool.Borrow();
    const CasterPool::Lease b = pool.Borrow();  // a is out: a second caster
    EXPECT_NE(&a.caster(), &b.caster());
    EXPECT_EQ(pool.casters_built(), 2u);
  }
  const CasterPool::Lease again = pool.Borrow();
  EXPECT_EQ(pool.casters_built(), 2u);
}

TEST(CasterPool, ThreadsBorrowingInTurnShareAtMostOneCasterEach) {
  const Peg peg;
  const CasterPool pool(peg.part_P, peg.fixed, {16, false});
  const VisibilityResult expected =
      VisibilityCaster(peg.part_P, peg.fixed, {16, false}).Compute(peg.eye, peg.poses[3]);
  constexpr int kThreads = 2, kBorrows = 20;
  std::vector<std::vector<VisibilityResult>> seen(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int k = 0; k < kBorrows; ++k) {
        const CasterPool::Lease lease = pool.Borrow();
        lease.caster().Compute(peg.eye, peg.poses[(t + k) % peg.poses.size()]);
        seen[t].push_back(lease.caster().Compute(peg.eye, peg.poses[3]));
      }
    });
  for (std::thread& t : threads) t.join();
  EXPECT_GE(pool.casters_built(), 1u);
  EXPECT_LE(pool.casters_built(), static_cast<std::size_t>(kThreads));
  for (const auto& results : seen)
    for (const VisibilityResult& r : results) ExpectSameBits(r, expected, 3);
}

}  // namespace
}  // namespace vahf::visibility
