#include "io/base/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace rt {
namespace {

// Creates a new temporary file in `folder`, exclusively: never an existing file, never through a
// symbolic link planted under its name, with the mode a new file gets (0666 less the umask). Its
// name is short whatever the target's (".rtcli-PID-N.tmp"), so any name the folder accepts for
// the target works.
int create_temporary(const std::filesystem::path& folder, std::string& temp, std::string& error) {
  for (unsigned n = 0; n < 1000; ++n) {
    temp = (folder / (".rtcli-" + std::to_string(::getpid()) + "-" + std::to_string(n) + ".tmp")).string();
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) break;  // a name taken (by a file or a link): try the next
  }
  error = "cannot create a temporary file " + temp + ": " + std::strerror(errno);
  return -1;
}

bool write_all(int fd, const std::vector<uint8_t>& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

bool write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error) {
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string temp;
  const int fd = create_temporary(folder, temp, error);
  if (fd < 0) return false;
  const bool written = write_all(fd, bytes) && ::fsync(fd) == 0;
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    error = "cannot write " + temp + ": " + std::strerror(written ? errno : write_errno);
    std::remove(temp.c_str());
    return false;
  }
  // rename() replaces the name itself: a link at `path` is replaced, not followed.
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    error = "cannot rename " + temp + " to " + path + ": " + std::strerror(errno);
    std::remove(temp.c_str());
    return false;
  }
  return true;
}

}  // namespace rt
