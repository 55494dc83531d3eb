#include "io/texture_library.h"

#include <algorithm>

#include "io/texture_file.h"

namespace rt {

uint32_t TextureLibrary::load(const TextureFileReference& ref, std::string& error, std::vector<std::string>& files) {
  const std::string key = ref.resolved_path + "\n" + std::to_string(static_cast<int>(ref.encoding));
  if (const auto it = indices_.find(key); it != indices_.end()) return it->second;
  const uint64_t budget =
      texels_ >= limits_.scene_texels ? 0 : std::min(limits_.texture_texels, limits_.scene_texels - texels_);
  std::string why;
  auto texture = load_texture(ref.resolved_path, ref.encoding, budget, why);
  uint32_t index = kNoTexture;
  if (!texture) {
    if (budget < limits_.texture_texels)
      why += " (all the scene's textures together may hold at most " + std::to_string(limits_.scene_texels) +
             " texels; README, \"Limits\")";
    // load_texture says what it found: a size ("expected an image of 1 to N texels, found ...")
    // or why the file could not be read.
    error = why.rfind("expected", 0) == 0 ? why : "expected a readable PNG or JPEG image; " + why;
  } else {
    files.push_back(ref.resolved_path);
    index = add(std::move(*texture));
  }
  indices_.emplace(key, index);
  return index;
}

uint32_t TextureLibrary::add(Texture texture) {
  count(texture);
  textures_.push_back(std::move(texture));
  return static_cast<uint32_t>(textures_.size() - 1);
}

void TextureLibrary::count(const Texture& t) {
  for (int level = 0; level < t.level_count(); ++level)
    texels_ += static_cast<uint64_t>(t.width(level)) * static_cast<uint64_t>(t.height(level));
}

}  // namespace rt
