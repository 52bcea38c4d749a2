// Fields packed into a byte string and read back in the same order: unsigned
// integers as 8 little-endian bytes, strings as their length then their
// bytes. For messages between the processes of one run (experiment/ranks.h),
// which must read the same on every machine whatever its byte order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "vahf/core/error.h"

namespace vahf {

class ByteWriter {
 public:
  void U64(std::uint64_t v) {
    for (int b = 0; b < 8; ++b)
      bytes_.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
  }
  void Str(const std::string& s) {
    U64(s.size());
    bytes_ += s;
  }
  const std::string& bytes() const { return bytes_; }
  std::string Take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a ByteWriter wrote; reading past the end is a ComputationError
// (kRefused): the bytes were not such a message.
class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  std::uint64_t U64() {
    Need(8);
    std::uint64_t v = 0;
    for (int b = 0; b < 8; ++b)
      v |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[at_ + b]))
           << (8 * b);
    at_ += 8;
    return v;
  }
  std::string Str() {
    const std::uint64_t n = U64();
    Need(n);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  void Need(std::uint64_t n) const {
    if (n > bytes_.size() - at_)
      throw ComputationError(ComputationError::Reason::kRefused,
                             "a message between ranks ends early: not one vahf wrote");
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace vahf
