// A directory of this process's own under the system's temporary directory
// ($TMPDIR, else /tmp), removed with everything in it when the object goes.
#pragma once

#include <string>

namespace vahf {

class TemporaryDirectory {
 public:
  // Creates TMP/PREFIX-XXXXXX (mkdtemp); a refusal is a ComputationError
  // (kRefused) naming the path.
  explicit TemporaryDirectory(const std::string& prefix);
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace vahf
