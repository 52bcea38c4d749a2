#include "vahf/core/digest.h"

#include <fmt/format.h>
#include <openssl/evp.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "vahf/core/error.h"

namespace vahf {

struct Sha256::Context {
  EVP_MD_CTX* md = nullptr;
};

Sha256::Sha256() : context_(std::make_unique<Context>()) {
  context_->md = EVP_MD_CTX_new();
  VAHF_CHECK(context_->md != nullptr, "EVP_MD_CTX_new failed (out of memory)");
  VAHF_CHECK(EVP_DigestInit_ex(context_->md, EVP_sha256(), nullptr) == 1,
             "EVP_DigestInit_ex(SHA-256) failed");
}

Sha256::~Sha256() { EVP_MD_CTX_free(context_->md); }

void Sha256::Update(std::string_view bytes) {
  VAHF_CHECK(!finished_, "Sha256::Update after HexDigest");
  VAHF_CHECK(EVP_DigestUpdate(context_->md, bytes.data(), bytes.size()) == 1,
             "EVP_DigestUpdate failed");
}

void Sha256::UpdateFromFile(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    throw InputError(path, "", "",
                     std::string("cannot open the file: ") + std::strerror(errno));
  }
  char buffer[1 << 16];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) Update({buffer, got});
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) {
    throw InputError(path, "", "",
                     std::string("cannot read the file: ") + std::strerror(error));
  }
}

std::string Sha256::HexDigest() {
  VAHF_CHECK(!finished_, "Sha256::HexDigest called twice");
  finished_ = true;
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  VAHF_CHECK(EVP_DigestFinal_ex(context_->md, digest, &size) == 1 && size == 32,
             "EVP_DigestFinal_ex failed");
  std::string hex;
  for (unsigned int i = 0; i < size; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

std::string Sha256Hex(std::string_view bytes) {
  Sha256 sha;
  sha.Update(bytes);
  return sha.HexDigest();
}

std::string Sha256OfFile(const std::string& path) {
  Sha256 sha;
  sha.UpdateFromFile(path);
  return sha.HexDigest();
}

}  // namespace vahf
