#include "vahf/report/build_info.h"

#include "vahf/report/build_info_values.h"  // generated

namespace vahf::report {

const BuildInfo& GetBuildInfo() {
  static const BuildInfo info{VAHF_BUILD_VERSION,     VAHF_BUILD_GIT_DESCRIBE,
                              VAHF_BUILD_COMPILER_ID, VAHF_BUILD_COMPILER_VERSION,
                              VAHF_BUILD_TYPE,        VAHF_BUILD_CXX_FLAGS};
  return info;
}

std::string VersionText(const BuildInfo& info) {
  if (info.git_describe.empty() || info.git_describe == "unknown") return info.version;
  return info.version + " (" + info.git_describe + ")";
}

}  // namespace vahf::report
