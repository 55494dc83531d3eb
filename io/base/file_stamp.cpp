#include "io/base/file_stamp.h"

#include <sys/stat.h>

namespace rt {

std::optional<FileStamp> stamp_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return FileStamp{static_cast<uint64_t>(st.st_dev), static_cast<uint64_t>(st.st_ino),
                   static_cast<uint64_t>(st.st_size),
                   static_cast<int64_t>(st.st_mtim.tv_sec) * 1000000000 + static_cast<int64_t>(st.st_mtim.tv_nsec)};
}

FileStamps FileStamps::of(std::vector<std::string> paths) {
  FileStamps s;
  s.paths = std::move(paths);
  for (const std::string& p : s.paths) s.stamps.push_back(stamp_file(p));
  return s;
}

bool FileStamps::current() const { return changed().empty(); }

std::vector<std::string> FileStamps::changed() const {
  std::vector<std::string> out;
  for (size_t i = 0; i < paths.size(); ++i)
    if (stamp_file(paths[i]) != stamps[i]) out.push_back(paths[i]);
  return out;
}

}  // namespace rt
