// SHA-256 (FIPS 180-4) through OpenSSL's EVP interface: file digests in a
// run's manifest, the digest of its results (report/manifest.h) and the
// check of each entry of its journal (experiment/journal.h).
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace vahf {

// An incremental digest: Update() any number of times, then HexDigest() once.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  void Update(std::string_view bytes);
  // Adds the bytes of a file; an unreadable file is an InputError naming it
  // and the operating system's reason.
  void UpdateFromFile(const std::string& path);
  // 64 lowercase hexadecimal digits; ends the digest (Update is then a bug).
  std::string HexDigest();

 private:
  struct Context;
  std::unique_ptr<Context> context_;
  bool finished_ = false;
};

// The digest of `bytes` as 64 lowercase hexadecimal digits.
std::string Sha256Hex(std::string_view bytes);

// The digest of a file's bytes; an unreadable file is an InputError naming it
// and the operating system's reason.
std::string Sha256OfFile(const std::string& path);

}  // namespace vahf
