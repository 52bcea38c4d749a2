// Build information: the version is the project's, and the recorded flags are
// the ones that make floating point reproducible (cmake/VahfFlags.cmake).
#include "vahf/report/build_info.h"

#include <ceres/version.h>
#include <embree3/rtcore_config.h>
#include <gsl/gsl_version.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
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

// The manifest's library versions are the ones whose headers this program was
// compiled against (where a header states one), and every library the run's
// numbers depend on has a version.
TEST(BuildInfo, RecordsTheVersionOfEveryLibraryLinked) {
  const std::map<std::string, std::string> libraries(GetBuildInfo().libraries.begin(),
                                                     GetBuildInfo().libraries.end());
  EXPECT_EQ(libraries.at("Ceres"), CERES_VERSION_STRING);
  EXPECT_EQ(libraries.at("GSL"), GSL_VERSION);
  EXPECT_EQ(libraries.at("Embree"), RTC_VERSION_STRING);
  for (const char* name :
       {"Simbody", "SUNDIALS", "Eigen", "nlohmann_json", "fmt", "CLI11"})
    EXPECT_TRUE(std::regex_match(libraries.at(name), std::regex(R"([0-9]+(\.[0-9]+)*)")))
        << name << " " << libraries.at(name);
  EXPECT_EQ(libraries.count("Random123"), 1u);  // "unknown": its package states none
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
