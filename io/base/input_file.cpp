#include "io/base/input_file.h"

#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace rt {
namespace {

std::string open_failure(int err) {
  switch (err) {
    case ENOENT: return "file not found";
    case ELOOP: return "is a loop of symbolic links (or too many links to follow), not a file";
    case EACCES: return "permission denied";
    case ENOTDIR: return "a part of the path is not a folder";
    case ENAMETOOLONG: return "the path is too long";
    case ENXIO: return "is a socket or a device without a reader, not a regular file";
    default: return std::string("cannot open: ") + std::strerror(err);
  }
}

std::string not_regular(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a named pipe (FIFO), not a regular file";
  if (S_ISCHR(mode)) return "is a character device, not a regular file";
  if (S_ISBLK(mode)) return "is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

template <class Container>
std::optional<Container> read_input(const std::string& path, uint64_t max_bytes, std::string& error) {
  if (path.empty()) {
    error = "file not found (the path is empty)";
    return std::nullopt;
  }
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0) {
    error = open_failure(errno);
    return std::nullopt;
  }
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) {
    error = std::string("cannot read: ") + std::strerror(errno);
    return std::nullopt;
  }
  if (!S_ISREG(st.st_mode)) {
    error = not_regular(st.st_mode);
    return std::nullopt;
  }
  const auto size = static_cast<uint64_t>(st.st_size);
  if (size > max_bytes) {
    error = "is " + format_bytes(size) + ", more than the " + format_bytes(max_bytes) + " this kind of file may have";
    return std::nullopt;
  }
  // Read what is there, never more than the limit: the file may change size while we read.
  Container data;
  data.resize(static_cast<size_t>(size));
  size_t done = 0;
  while (true) {
    if (done == data.size()) {
      if (data.size() >= max_bytes) {
        char probe;
        const ssize_t extra = ::read(file.fd, &probe, 1);
        if (extra > 0) {
          error = "grew past the " + format_bytes(max_bytes) + " this kind of file may have while being read";
          return std::nullopt;
        }
        break;
      }
      data.resize(static_cast<size_t>(std::min<uint64_t>(max_bytes, std::max<uint64_t>(4096, 2 * data.size()))));
    }
    const ssize_t n = ::read(file.fd, data.data() + done, data.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      error = std::string("cannot read: ") + std::strerror(errno);
      return std::nullopt;
    }
    if (n == 0) break;
    done += static_cast<size_t>(n);
  }
  data.resize(done);
  return data;
}

}  // namespace

std::optional<std::string> read_input_text(const std::string& path, uint64_t max_bytes, std::string& error) {
  return read_input<std::string>(path, max_bytes, error);
}

std::optional<std::vector<unsigned char>> read_input_bytes(const std::string& path, uint64_t max_bytes,
                                                           std::string& error) {
  return read_input<std::vector<unsigned char>>(path, max_bytes, error);
}

std::string format_bytes(uint64_t bytes) {
  constexpr uint64_t kKiB = 1024, kMiB = kKiB * 1024, kGiB = kMiB * 1024;
  char buf[48];
  const auto show = [&](uint64_t unit, const char* name) {
    if (bytes % unit == 0)
      std::snprintf(buf, sizeof buf, "%llu %s", static_cast<unsigned long long>(bytes / unit), name);
    else std::snprintf(buf, sizeof buf, "%.1f %s", static_cast<double>(bytes) / static_cast<double>(unit), name);
  };
  if (bytes >= kGiB) show(kGiB, "GiB");
  else if (bytes >= kMiB) show(kMiB, "MiB");
  else if (bytes >= kKiB) show(kKiB, "KiB");
  else std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(bytes));
  return buf;
}

bool is_inside_folder(const std::string& path, const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path inner = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return false;
  fs::path outer = fs::weakly_canonical(fs::absolute(folder.empty() ? "." : folder, ec), ec);
  if (ec) return false;
  if (!outer.has_filename()) outer = outer.parent_path();  // "dir/" -> "dir"
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return i != inner.end();  // something below the folder, not the folder itself
}

std::string resolve_path(const std::string& folder, const std::string& file) {
  const std::filesystem::path p(file);
  return p.is_absolute() ? p.string() : (std::filesystem::path(folder) / p).lexically_normal().string();
}

}  // namespace rt
