// A file's whole contents as bytes, for the readers of every input and
// stored result (scene and experiment JSON, lab tables, handbooks, a run's
// result files, the journal).
#pragma once

#include <optional>
#include <string>

namespace vahf {

// The bytes of the file (or pipe) at `path`; nothing when it is missing, a
// directory, or cannot be opened or read. The caller says what that means
// for its input (an InputError naming the file, or no journal yet).
std::optional<std::string> ReadWholeFile(const std::string& path);

}  // namespace vahf
