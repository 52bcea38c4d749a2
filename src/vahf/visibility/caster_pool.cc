#include "vahf/visibility/caster_pool.h"

#include <utility>

namespace vahf::visibility {

CasterPool::CasterPool(geometry::TriangleMesh part_mesh_P,
                       std::vector<Occluder> occluders, CasterOptions options)
    : part_mesh_P_(std::move(part_mesh_P)),
      occluders_(std::move(occluders)),
      options_(options) {}

CasterPool::~CasterPool() = default;

CasterPool::Lease::Lease(const CasterPool* pool, std::unique_ptr<VisibilityCaster> caster)
    : pool_(pool), caster_(std::move(caster)) {}

CasterPool::Lease::Lease(Lease&& other) noexcept
    : pool_(other.pool_), caster_(std::move(other.caster_)) {}

CasterPool::Lease::~Lease() {
  if (caster_) pool_->GiveBack(std::move(caster_));
}

CasterPool::Lease CasterPool::Borrow() const {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!idle_.empty()) {
      std::unique_ptr<VisibilityCaster> caster = std::move(idle_.back());
      idle_.pop_back();
      return Lease(this, std::move(caster));
    }
  }
  // Built outside the lock: another thread may borrow or build meanwhile.
  auto caster = std::make_unique<VisibilityCaster>(part_mesh_P_, occluders_, options_);
  const std::lock_guard<std::mutex> lock(mutex_);
  ++built_;
  return Lease(this, std::move(caster));
}

void CasterPool::GiveBack(std::unique_ptr<VisibilityCaster> caster) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  idle_.push_back(std::move(caster));
}

std::size_t CasterPool::casters_built() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return built_;
}

}  // namespace vahf::visibility
