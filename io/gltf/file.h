// A glTF 2.0 file (.gltf with external or embedded buffers, or .glb) parsed by tinygltf and
// checked for what tinygltf leaves to its caller: a limit on the JSON's size and nesting,
// regular files only for external buffers (io/base/input_file.h) within a byte budget, every
// bufferView inside its buffer, and no required extension that rtcli does not implement.
// tinygltf's own messages are cleaned; an exception inside it is a broken file, not a crash.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "io/base/load_options.h"
#include "io/base/reporter.h"

namespace tinygltf {
class Model;
}

namespace rt {

struct GltfFile {
  std::shared_ptr<const tinygltf::Model> model;
  std::vector<std::string> files;  // every file read: the model and its external buffers
};

// `bytes` are the whole file (.glb if they start with "glTF", else JSON text); external buffers
// resolve against `base_dir`. Problems go to `report` (tinygltf's warnings cleaned), which from
// then on finds line:column in a .gltf's text; on failure, no model.
GltfFile parse_gltf(const std::vector<unsigned char>& bytes, const std::string& base_dir, const LoadLimits& limits,
                    Reporter& report);

// The error for an image or buffer URI that leaves the model's folder (LoadLimits::outside_files).
std::string outside_folder_message(const std::string& uri, const std::string& base_dir);

}  // namespace rt
