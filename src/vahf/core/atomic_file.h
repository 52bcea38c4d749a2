// Writes a file whole or not at all: the text goes to PATH.partial, which is
// synced to disk and renamed into place only once complete, and the folder is
// synced after the rename, so an interrupted run never leaves a half-written
// result and a file that is there is kept.
#pragma once

#include <string>
#include <system_error>

namespace vahf {

// An unwritable path is an InputError naming it and the operating system's
// reason (a full disk, a read-only folder); no .partial file remains.
void WriteFileAtomically(const std::string& path, const std::string& text);

// Syncs the folder at `path` to disk (fsync), so that the names created,
// renamed or removed in it are kept; the operating system's error, if any.
// A file system that cannot sync a folder (EINVAL) is no error.
std::error_code SyncDirectory(const std::string& path);

}  // namespace vahf
