#include "io/assemble/texture_library.h"

#include "io/assemble/load_cache.h"
#include "io/image/environment_file.h"

namespace rt {

uint32_t TextureLibrary::load(const TextureFileReference& ref, Reporter& report, std::vector<std::string>& files) {
  const std::string key = ref.resolved_path + "\n" + std::to_string(static_cast<int>(ref.encoding));
  if (const auto it = indices_.find(key); it != indices_.end()) return it->second;
  if (cache_) {
    if (const LoadCache::Image* kept = cache_->image(key, usage_, limits_)) {
      usage_.texels += kept->texels;
      files.push_back(ref.resolved_path);
      const uint32_t index = add(kept->texture);
      indices_.emplace(key, index);
      return index;
    }
  }
  TextureError error;
  const FileStamps stamps = FileStamps::of({ref.resolved_path});  // before reading: a later change shows
  const uint64_t texels_before = usage_.texels;
  auto texture = load_texture(ref.resolved_path, ref.encoding, limits_, usage_, error);
  if (texture && cache_) cache_->keep(key, LoadCache::Image{stamps, *texture, usage_.texels - texels_before});
  uint32_t index = kNoTexture;
  if (texture) {
    files.push_back(ref.resolved_path);
    index = add(std::move(*texture));
  } else if (error.over_budget) {
    report.over_limit(ref.pointer, error.message);
  } else {
    const bool says_expected = error.message.rfind("expected", 0) == 0;
    report.error(ref.pointer,
                 says_expected ? error.message : "expected a readable PNG, JPEG or WebP image; " + error.message);
  }
  indices_.emplace(key, index);
  return index;
}

std::shared_ptr<const EnvironmentImage> TextureLibrary::environment(const std::string& path, std::string& why,
                                                                    std::vector<std::string>& files) {
  std::shared_ptr<const EnvironmentImage> image;
  if (const LoadCache::Environment* kept = cache_ ? cache_->environment(path, usage_, limits_) : nullptr) {
    image = kept->image;
    usage_.texels += kept->texels;
  } else {
    const FileStamps stamps = FileStamps::of({path});  // before reading: a later change shows
    const uint64_t before = usage_.texels;
    image = load_environment_image(path, limits_, usage_, why);
    if (image && cache_) cache_->keep(path, LoadCache::Environment{stamps, image, usage_.texels - before});
  }
  if (image) files.push_back(path);
  return image;
}

uint32_t TextureLibrary::add(Texture texture) {
  textures_.push_back(std::move(texture));
  return static_cast<uint32_t>(textures_.size() - 1);
}

}  // namespace rt
