#include "vahf/core/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "vahf/core/error.h"

namespace vahf {

void WriteFileAtomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "", "", "cannot open the file for writing");
    out << text;
    out.close();
    if (!out) {
      std::remove(temporary.c_str());
      throw InputError(path, "", "", "writing the file failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(path, "", "", "cannot move the finished file into place: " + ec.message());
  }
}

}  // namespace vahf
