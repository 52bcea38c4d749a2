#include "vahf/core/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "vahf/core/error.h"

namespace vahf {

void WriteFileAtomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw InputError(
          path, "", "",
          std::string("cannot open the file for writing: ") + std::strerror(errno));
    }
    out << text;
    out.close();
    if (!out) {
      const int error = errno;
      std::remove(temporary.c_str());
      throw InputError(path, "", "",
                       std::string("writing the file failed: ") + std::strerror(error));
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(path, "", "",
                     "cannot move the finished file into place: " + ec.message());
  }
}

}  // namespace vahf
