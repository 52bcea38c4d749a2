// The casters of one part against its fixed parts, built once and lent out:
// a caster (visibility.h: Embree device, BVHs, the part's instance) costs far
// more to build than a V, and every trial of a part and experiment casts
// against the same meshes. The only thing a caster changes as it casts is the
// transform of the part's instance, which each Compute sets for its own pose,
// so a caster lent again gives the same bits as a fresh one
// (tests/visibility/caster_pool_test.cc).
//
// Ownership: the pool owns the meshes and every caster it built. A caster
// idle in the pool is touched by nobody; a lent one only by the holder of its
// Lease, on one thread at a time, until the Lease ends and gives it back.
// Borrow is thread-safe and const: lending changes no result, so a pool can
// sit in a model shared read-only by many threads. A caster is built on first
// need, when none is idle, so a pool holds as many as were ever in use at
// once (at most the number of threads that borrow).
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "vahf/geometry/tessellation.h"
#include "vahf/visibility/visibility.h"

namespace vahf::visibility {

class CasterPool {
 public:
  // The meshes and options of every caster it will build (the
  // VisibilityCaster constructor's); nothing is built yet.
  CasterPool(geometry::TriangleMesh part_mesh_P, std::vector<Occluder> occluders,
             CasterOptions options);
  ~CasterPool();
  CasterPool(const CasterPool&) = delete;
  CasterPool& operator=(const CasterPool&) = delete;

  // One caster, for its holder alone until the Lease ends; it must end before
  // the pool does.
  class Lease {
   public:
    Lease(Lease&& other) noexcept;
    Lease& operator=(Lease&&) = delete;
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease();  // gives the caster back

    VisibilityCaster& caster() const { return *caster_; }

   private:
    friend class CasterPool;
    Lease(const CasterPool* pool, std::unique_ptr<VisibilityCaster> caster);
    const CasterPool* pool_;
    std::unique_ptr<VisibilityCaster> caster_;
  };

  // An idle caster, or a new one when none is. Throws what the
  // VisibilityCaster constructor throws (then nothing is counted as built).
  Lease Borrow() const;

  // How many casters the pool has built (for tests and benchmarks).
  std::size_t casters_built() const;

 private:
  void GiveBack(std::unique_ptr<VisibilityCaster> caster) const;

  const geometry::TriangleMesh part_mesh_P_;
  const std::vector<Occluder> occluders_;
  const CasterOptions options_;
  // Guards idle_ and built_: the only state Borrow and GiveBack change.
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<VisibilityCaster>> idle_;
  mutable std::size_t built_ = 0;
};

}  // namespace vahf::visibility
