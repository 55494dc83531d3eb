// Reading whole input files (scenes, glTF models, their buffers) safely. Only regular files are
// read: a FIFO would block forever, /dev/zero never ends, a folder is no file. The file is opened
// first and checked through its descriptor, so it cannot be swapped between check and read, and
// at most `max_bytes` are read, whatever size the file claims. Every failure is one sentence
// that says what the path is ("is a named pipe (FIFO), not a regular file").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rt {

std::optional<std::string> read_input_text(const std::string& path, uint64_t max_bytes, std::string& error);
std::optional<std::vector<unsigned char>> read_input_bytes(const std::string& path, uint64_t max_bytes,
                                                           std::string& error);

// A path as written in a scene file: relative paths resolve against the scene file's folder.
std::string resolve_path(const std::string& folder, const std::string& file);

// Whether `path` lies inside `folder` (at any depth), both resolved: symbolic links followed,
// "." and ".." removed. A path that cannot be resolved is outside.
bool is_inside_folder(const std::string& path, const std::string& folder);

// "64 MiB", "1.5 GiB", "812 bytes": sizes in limit messages.
std::string format_bytes(uint64_t bytes);

}  // namespace rt
