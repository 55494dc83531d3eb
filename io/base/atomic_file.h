// Writing a file so that readers see the old content or the new, never half of either: the
// bytes go to a new temporary file in the same folder (created exclusively, never through a
// link), are flushed to disk, and the temporary file is renamed over the target. On any failure
// the temporary file is removed. Every output rtcli writes goes through here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rt {

bool write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error);

}  // namespace rt
