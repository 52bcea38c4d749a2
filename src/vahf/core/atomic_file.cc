#include "vahf/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "vahf/core/error.h"

namespace vahf {
namespace {

// Writes `text` to the open file `fd`, syncs and closes it; 0 or the errno
// of what failed.
int WriteAndSync(int fd, const std::string& text) {
  int error = 0;
  for (std::size_t done = 0; done < text.size() && error == 0;) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) error = n < 0 ? errno : EIO;
    if (n > 0) done += static_cast<std::size_t>(n);
  }
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  return error;
}

}  // namespace

std::error_code SyncDirectory(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return {errno, std::generic_category()};
  std::error_code result;
  if (::fsync(fd) != 0 && errno != EINVAL) result = {errno, std::generic_category()};
  ::close(fd);
  return result;
}

void WriteFileAtomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  const int fd =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw InputError(
        path, "", "",
        std::string("cannot open the file for writing: ") + std::strerror(errno));
  }
  if (const int error = WriteAndSync(fd, text); error != 0) {
    std::remove(temporary.c_str());
    throw InputError(path, "", "",
                     std::string("writing the file failed: ") + std::strerror(error));
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(path, "", "",
                     "cannot move the finished file into place: " + ec.message());
  }
  std::string folder = std::filesystem::path(path).parent_path().string();
  if (folder.empty()) folder = ".";
  if (const std::error_code synced = SyncDirectory(folder))
    throw InputError(folder, "", "",
                     "cannot sync the folder to disk: " + synced.message());
}

}  // namespace vahf
