// The texture keys of a material -- "texture", "specular_texture", "bump", "normal_map" -- each a
// file name or an object with "file" and the mapping keys (docs/rendering.md, "Textures"). The files are only
// named here; the scene builder loads each one once.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/texture/texture_slot.h"
#include "io/image/texture_file.h"
#include "io/json/reader.h"

namespace rt {

// A texture file a material slot names, for the builder to load.
struct TextureFileReference {
  std::string file;           // as written
  std::string resolved_path;  // against the scene file's folder
  TextureEncoding encoding = TextureEncoding::kSrgb;
  std::string pointer;  // of the file name, where problems with the file are reported
};

// Reads one slot's value into `mapping`; `extra` reads the keys only this slot has (bump
// strength, normal map scale) from the object form. Nothing when the value is in error.
std::optional<TextureFileReference> parse_texture_slot(const JsonReader& r, const Json& value, const std::string& ptr,
                                                       const std::string& scene_folder, TextureEncoding encoding,
                                                       TextureMapping& mapping,
                                                       const std::function<void(ObjectReader&)>& extra = {});

}  // namespace rt
