// An owning pointer that copies what it points to (T::Clone()), so that a
// value holding a polymorphic part stays an ordinary copyable value.
#pragma once

#include <memory>
#include <utility>

namespace vahf::core {

template <class T>
class ClonePtr {
 public:
  ClonePtr() = default;
  explicit ClonePtr(std::unique_ptr<T> p) : p_(std::move(p)) {}
  ClonePtr(const ClonePtr& other) : p_(other.p_ ? other.p_->Clone() : nullptr) {}
  ClonePtr(ClonePtr&&) noexcept = default;
  ClonePtr& operator=(const ClonePtr& other) {
    if (this != &other) p_ = other.p_ ? other.p_->Clone() : nullptr;
    return *this;
  }
  ClonePtr& operator=(ClonePtr&&) noexcept = default;
  ~ClonePtr() = default;

  T* get() const { return p_.get(); }
  T* operator->() const { return p_.get(); }
  explicit operator bool() const { return p_ != nullptr; }

 private:
  std::unique_ptr<T> p_;
};

}  // namespace vahf::core
