// Files for the scene and experiment loader tests: a fresh directory per
// running test, and writing a file there.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "vahf/core/error.h"

namespace vahf::scene::testing {

inline std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A directory of its own under ::testing::TempDir()/`folder` for the running test.
inline std::filesystem::path TestDir(const std::string& folder) {
  const ::testing::TestInfo* info =
      ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / folder /
      (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  EXPECT_TRUE(out) << "cannot write " << path;
  return path.string();
}

inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);) out.push_back(line);
  return out;
}

// Expects `load()` to throw one InputError naming `file` at `where`, whose rule
// contains `rule` and, unless `value` is empty, whose value contains `value`
// (ignoring case).
template <class Load>
void ExpectInputError(const Load& load, const std::string& file, const std::string& where,
                      const std::string& rule, const std::string& value = "") {
  try {
    load();
    ADD_FAILURE() << "no InputError; expected one at " << where << " (" << rule << ")";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.where(), where) << e.what();
    EXPECT_THAT(e.rule(), ::testing::HasSubstr(rule)) << e.what();
    if (!value.empty()) {
      EXPECT_THAT(Lower(e.value()), ::testing::HasSubstr(Lower(value))) << e.what();
    }
  }
}

}  // namespace vahf::scene::testing
