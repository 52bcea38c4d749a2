#include "vahf/rng/stream.h"

#include <Random123/philox.h>

#include <Random123/boxmuller.hpp>
#include <Random123/uniform.hpp>

namespace vahf::rng {

Stream::Stream(StreamKey key, std::uint64_t decision, Purpose purpose)
    : key_{key.seed, key.trial},
      counter_{decision, static_cast<std::uint64_t>(purpose), 0, 0} {}

void Stream::Refill() {
  r123::Philox4x64 philox;
  const r123::Philox4x64::ctr_type ctr = {
      {counter_[0], counter_[1], counter_[2], counter_[3]}};
  const r123::Philox4x64::key_type key = {{key_[0], key_[1]}};
  const r123::Philox4x64::ctr_type out = philox(ctr, key);
  for (int i = 0; i < 4; ++i) block_[i] = out.v[i];
  ++counter_[2];
  used_ = 0;
}

std::uint64_t Stream::Bits() {
  if (used_ == 4) Refill();
  return block_[used_++];
}

double Stream::Uniform() { return r123::u01<double>(Bits()); }

double Stream::Normal() {
  if (has_spare_normal_) {
    has_spare_normal_ = false;
    return spare_normal_;
  }
  const std::uint64_t a = Bits();
  const std::uint64_t b = Bits();
  const r123::double2 pair = r123::boxmuller(a, b);
  spare_normal_ = pair.y;
  has_spare_normal_ = true;
  return pair.x;
}

}  // namespace vahf::rng
