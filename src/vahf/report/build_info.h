// What built this program, for the manifest: a reviewer re-running a seeded
// experiment sees whether version, compiler or floating-point flags differ
// (docs/design.md decision 9). Captured when CMake configures the build
// (cmake/VahfBuildInfo.cmake).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vahf::report {

struct BuildInfo {
  std::string version;           // PROJECT_VERSION of the top CMakeLists.txt
  std::string git_describe;      // `git describe --always --dirty`, or "unknown"
  std::string compiler_id;       // CMAKE_CXX_COMPILER_ID, e.g. "GNU"
  std::string compiler_version;  // e.g. "12.2.0"
  std::string build_type;        // CMAKE_BUILD_TYPE
  std::string cxx_flags;         // the C++ flags every vahf source is compiled with
  // The libraries linked, name -> version as CMake's find_package found it
  // ("Simbody" -> "3.7"; "unknown" where the package states none).
  std::vector<std::pair<std::string, std::string>> libraries;
};

const BuildInfo& GetBuildInfo();

// "0.1.0 (c18c587-dirty)", or "0.1.0" when git_describe is unknown.
std::string VersionText(const BuildInfo& info = GetBuildInfo());

}  // namespace vahf::report
