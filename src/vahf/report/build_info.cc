#include "vahf/report/build_info.h"

#include "vahf/report/build_info_values.h"  // generated

namespace vahf::report {

namespace {

// "Simbody=3.7;GSL=2.7.1;" -> {{"Simbody", "3.7"}, {"GSL", "2.7.1"}}.
std::vector<std::pair<std::string, std::string>> ParseLibraries(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find(';', begin);
    if (end == std::string::npos) end = text.size();
    const std::string entry = text.substr(begin, end - begin);
    const std::size_t eq = entry.find('=');
    if (eq != std::string::npos)
      out.emplace_back(entry.substr(0, eq), entry.substr(eq + 1));
    begin = end + 1;
  }
  return out;
}

}  // namespace

const BuildInfo& GetBuildInfo() {
  static const BuildInfo info{VAHF_BUILD_VERSION,
                              VAHF_BUILD_GIT_DESCRIBE,
                              VAHF_BUILD_COMPILER_ID,
                              VAHF_BUILD_COMPILER_VERSION,
                              VAHF_BUILD_TYPE,
                              VAHF_BUILD_CXX_FLAGS,
                              ParseLibraries(VAHF_BUILD_LIBRARIES)};
  return info;
}

std::string VersionText(const BuildInfo& info) {
  if (info.git_describe.empty() || info.git_describe == "unknown") return info.version;
  return info.version + " (" + info.git_describe + ")";
}

}  // namespace vahf::report
