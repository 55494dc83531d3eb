#include "io/assemble/load_cache.h"

namespace rt {
namespace {

bool fits(const LimitUsage& usage, const LimitUsage& more, const LoadLimits& limits) {
  return more.vertices <= limits.vertices - std::min(usage.vertices, limits.vertices) &&
         more.triangles <= limits.triangles - std::min(usage.triangles, limits.triangles) &&
         more.texels <= limits.scene_texels - std::min(usage.texels, limits.scene_texels) &&
         more.animation_keys <= limits.animation_keys - std::min(usage.animation_keys, limits.animation_keys);
}

// The item under `key`, if its files are unchanged and it fits; a changed one is dropped.
template <class Item, class Used>
const Item* find(std::map<std::string, std::unique_ptr<Item>>& items, const std::string& key,
                 const FileStamps Item::*files, Used used, const LimitUsage& usage, const LoadLimits& limits,
                 int& kept) {
  const auto it = items.find(key);
  if (it == items.end()) return nullptr;
  if (!((*it->second).*files).current()) {
    items.erase(it);
    return nullptr;
  }
  if (!fits(usage, used(*it->second), limits)) return nullptr;
  ++kept;
  return it->second.get();
}

LimitUsage texels_only(uint64_t texels) {
  LimitUsage u;
  u.texels = texels;
  return u;
}

}  // namespace

const LoadCache::Model* LoadCache::model(const std::string& key, const LimitUsage& usage, const LoadLimits& limits) {
  return find(
      models_, key, &Model::files, [](const Model& m) { return m.used; }, usage, limits, kept_);
}

const LoadCache::Image* LoadCache::image(const std::string& key, const LimitUsage& usage, const LoadLimits& limits) {
  return find(
      images_, key, &Image::file, [](const Image& i) { return texels_only(i.texels); }, usage, limits, kept_);
}

const LoadCache::Environment* LoadCache::environment(const std::string& key, const LimitUsage& usage,
                                                     const LoadLimits& limits) {
  return find(
      environments_, key, &Environment::file, [](const Environment& e) { return texels_only(e.texels); }, usage, limits,
      kept_);
}

}  // namespace rt
