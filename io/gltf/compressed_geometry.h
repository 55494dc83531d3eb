// Compressed glTF geometry, decoded before the file is read as any other (docs/scene-format.md,
// "glTF compression"): KHR_draco_mesh_compression (Debian's libdraco, Apache-2.0) and
// EXT_meshopt_compression (Debian's meshoptimizer, MIT). The document is rewritten: each Draco
// primitive's accessors and each meshopt buffer view point at a new buffer holding the decoded
// data (a data URI), the extensions are taken out of the primitives, views and the
// extensions lists, and meshopt's fallback buffers (which have no data) become empty. Everything
// read from the compressed data is checked first (indices, sizes, attribute ids, the decoded
// bytes against the model's budget): a hostile file is an error, never a crash.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/base/reporter.h"
#include "io/json/document.h"

namespace rt {

// Whether the document uses either extension (then it needs decompress_geometry before loading).
bool uses_compressed_geometry(const Json& document);

// The buffers a document without its meshes would load, as decompress_geometry needs them.
// `buffers[i]` is buffer i's bytes. False (reported) when the document cannot be decoded; the
// decoded bytes must stay within `budget`.
bool decompress_geometry(Json& document, const std::vector<std::vector<unsigned char>>& buffers, uint64_t budget,
                         Reporter& report);

// A buffer's JSON for bytes held in the document itself (a base64 data URI).
Json embedded_buffer(const std::vector<unsigned char>& bytes);

}  // namespace rt
