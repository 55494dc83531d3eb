// `rtcli validate FILE... [--json]`: checks scene files (.json) and glTF models (.gltf/.glb)
// without rendering: the loader's checks and the JSON Schema. Exit 0 when every file is valid,
// 2 otherwise.
#pragma once

#include <string>
#include <vector>

namespace rt {

struct ValidateCommand {
  std::vector<std::string> files;
  bool json = false;                 // print one JSON array of diagnostics instead of text
  bool allow_outside_files = false;  // glTF files may read images and buffers outside their folder
};

int run_validate(const ValidateCommand& cmd);

}  // namespace rt
