// Build information: the version is the project's, and the recorded flags are
// the ones that make floating point reproducible (cmake/VahfFlags.cmake).
#include "vahf/report/build_info.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace vahf::report {
namespace {

TEST(BuildInfo, VersionIsTheProjectVersion) {
  std::ifstream in(std::string(VAHF_SOURCE_DIR) + "/CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string cmake = text.str();
  ASSERT_TRUE(
      std::regex_search(cmake, m, std::regex(R"(project\(vahf VERSION ([0-9.]+))")));
  EXPECT_EQ(GetBuildInfo().version, m[1].str());
}

TEST(BuildInfo, RecordsCompilerTypeAndFlags) {
  const BuildInfo& b = GetBuildInfo();
  EXPECT_FALSE(b.git_describe.empty());
  EXPECT_FALSE(b.compiler_id.empty());
  EXPECT_FALSE(b.compiler_version.empty());
  EXPECT_FALSE(b.build_type.empty());
  EXPECT_NE(b.cxx_flags.find("-ffp-contract=off"), std::string::npos) << b.cxx_flags;
  EXPECT_NE(b.cxx_flags.find("-fno-fast-math"), std::string::npos) << b.cxx_flags;
  EXPECT_EQ(b.cxx_flags.find("-march=native"), std::string::npos) << b.cxx_flags;
}

TEST(BuildInfo, VersionText) {
  BuildInfo b;
  b.version = "0.1.0";
  b.git_describe = "unknown";
  EXPECT_EQ(VersionText(b), "0.1.0");
  b.git_describe = "c18c587-dirty";
  EXPECT_EQ(VersionText(b), "0.1.0 (c18c587-dirty)");
}

}  // namespace
}  // namespace vahf::report
