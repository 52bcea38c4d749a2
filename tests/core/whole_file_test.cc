// ReadWholeFile (core/whole_file.h): a file's exact bytes, a pipe's, and
// nothing for a missing path or a directory.
#include "vahf/core/whole_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "vahf/core/temporary_directory.h"

namespace vahf {
namespace {

TEST(WholeFile, AFilesBytesExactly) {
  const TemporaryDirectory dir("vahf-whole-file");
  const std::string path = dir.path() + "/f.bin";
  const std::string bytes("a\0b\r\nc", 6);
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(ReadWholeFile(path), bytes);
  std::ofstream(dir.path() + "/empty", std::ios::binary);
  EXPECT_EQ(ReadWholeFile(dir.path() + "/empty"), "");
}

TEST(WholeFile, NothingForAMissingPathOrADirectory) {
  const TemporaryDirectory dir("vahf-whole-file");
  EXPECT_FALSE(ReadWholeFile(dir.path() + "/missing"));
  EXPECT_FALSE(ReadWholeFile(dir.path()));
}

// As bash's <(...) gives one: vahf run <(generate-experiment) reads it.
TEST(WholeFile, APipesBytes) {
  const TemporaryDirectory dir("vahf-whole-file");
  const std::string path = dir.path() + "/pipe";
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(path, std::ios::binary) << "{\"k\": 1}"; });
  const std::optional<std::string> text = ReadWholeFile(path);
  writer.join();
  EXPECT_EQ(text, "{\"k\": 1}");
}

}  // namespace
}  // namespace vahf
