#include "vahf/core/whole_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace vahf {

std::optional<std::string> ReadWholeFile(const std::string& path) {
  std::error_code error;
  // A pipe (bash's <(...)) is read like a file; a directory opens but has no bytes.
  if (std::filesystem::is_directory(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return buffer.str();
}

}  // namespace vahf
