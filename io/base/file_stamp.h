// What says a file changed without reading it: its device, inode, size and modification time.
// An editor that saves by writing a new file and renaming it over the old one changes the inode;
// one that writes in place changes the time and usually the size. `rtcli watch` polls these for
// every file a scene read, and the load cache (io/assemble/load_cache.h) keeps what it decoded
// from a file only while its stamp stays the same.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rt {

struct FileStamp {
  uint64_t device = 0, inode = 0, size = 0;
  int64_t modified_ns = 0;
  bool operator==(const FileStamp&) const = default;
};

// The file's stamp now; nothing if it cannot be read (missing, mid-rename).
std::optional<FileStamp> stamp_file(const std::string& path);

// Stamps of several files at one moment, to compare with a later look.
struct FileStamps {
  std::vector<std::string> paths;
  std::vector<std::optional<FileStamp>> stamps;

  static FileStamps of(std::vector<std::string> paths);
  // Whether every file still has the stamp it had (a file that was missing is still missing).
  bool current() const;
  // The files whose stamp changed.
  std::vector<std::string> changed() const;
};

}  // namespace rt
