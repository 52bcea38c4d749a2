// SHA-256 against the FIPS 180-2 examples (Appendix B: "abc" and the 448-bit
// message) and the empty message; the file digest equals the digest of the
// file's bytes; an unreadable file names itself and the reason.
#include "vahf/core/digest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "vahf/core/error.h"

namespace vahf {
namespace {

TEST(Sha256, Fips180Vectors) {
  EXPECT_EQ(Sha256Hex("abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(Sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(Sha256Hex(""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256, IncrementalEqualsWhole) {
  Sha256 sha;
  sha.Update("ab");
  sha.Update("");
  sha.Update("c");
  EXPECT_EQ(sha.HexDigest(), Sha256Hex("abc"));
}

TEST(Sha256, OfFile) {
  const std::string path = ::testing::TempDir() + "/digest_test_file.bin";
  std::string bytes(200000, '\0');  // more than one read buffer, with NULs
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<char>(i * 31 % 251);
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(Sha256OfFile(path), Sha256Hex(bytes));
  std::remove(path.c_str());
}

TEST(Sha256, UnreadableFileIsAnInputError) {
  const std::string path = ::testing::TempDir() + "/no_such_file_here.json";
  try {
    Sha256OfFile(path);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.rule(), "cannot open the file: No such file or directory");
  }
  try {
    Sha256OfFile(::testing::TempDir());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "cannot read the file: Is a directory");
  }
}

}  // namespace
}  // namespace vahf
