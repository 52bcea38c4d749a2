#include "vahf/core/temporary_directory.h"

#include <stdlib.h>  // mkdtemp (POSIX)

#include <filesystem>

#include "vahf/core/error.h"

namespace vahf {

TemporaryDirectory::TemporaryDirectory(const std::string& prefix) {
  std::string pattern =
      (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (!mkdtemp(pattern.data()))
    throw ComputationError(ComputationError::Reason::kRefused,
                           "cannot create a temporary directory " + pattern);
  path_ = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace vahf
