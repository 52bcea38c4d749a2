// Writes a file whole or not at all: the text goes to PATH.partial, which is
// renamed into place only once complete, so an interrupted run never leaves a
// half-written result.
#pragma once

#include <string>

namespace vahf {

// An unwritable path is an InputError naming it and the operating system's
// reason; no .partial file remains.
void WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace vahf
