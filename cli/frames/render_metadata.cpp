#include "cli/frames/render_metadata.h"

#include <cstdio>
#include <fstream>

namespace rt {

std::string float_text(float v) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%a", static_cast<double>(v));
  return buffer;
}

uint64_t fnv1a(const void* data, size_t size, uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) {
    hash ^= p[i];
    hash *= 0x100000001b3ull;
  }
  return hash;
}

std::string hex64(uint64_t value) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
  return buffer;
}

std::string hash_files(const std::vector<std::string>& paths) {
  uint64_t hash = kFnvBasis;
  std::vector<char> chunk(1 << 16);
  for (const std::string& path : paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    while (in) {
      in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
      hash = fnv1a(chunk.data(), static_cast<size_t>(in.gcount()), hash);
    }
    const char separator = 0;  // "ab" + "c" and "a" + "bc" differ
    hash = fnv1a(&separator, 1, hash);
  }
  return hex64(hash);
}

std::map<std::string, std::string> render_attributes(const RenderIdentity& id, int frame, const PixelWindow& window) {
  std::map<std::string, std::string> out = {
      {exr_key::kVersion, RTCLI_VERSION},
      {exr_key::kScene, id.scene},
      {exr_key::kSceneHash, id.scene_hash},
      {exr_key::kSettings, id.settings},
      {exr_key::kSettingsHash, hex64(fnv1a(id.settings.data(), id.settings.size()))},
      {exr_key::kFrame, std::to_string(frame)},
      {exr_key::kCrop, std::to_string(window.x0) + "," + std::to_string(window.y0) + "," + std::to_string(window.x1) +
                           "," + std::to_string(window.y1)},
      {exr_key::kSeed, std::to_string(id.seed)},
      {exr_key::kExposure, float_text(id.display.exposure)},
      {exr_key::kToneMap, std::string(kToneMaps.name(id.display.curve))},
      {exr_key::kFps, float_text(id.fps)},
  };
  if (!id.tile.empty()) out[exr_key::kTile] = id.tile;
  return out;
}

bool same_render(const std::map<std::string, std::string>& file, const std::map<std::string, std::string>& expected) {
  for (const char* key :
       {exr_key::kSceneHash, exr_key::kSettingsHash, exr_key::kFrame, exr_key::kCrop, exr_key::kTile}) {
    const auto a = file.find(key), b = expected.find(key);
    if ((a == file.end()) != (b == expected.end())) return false;
    if (a != file.end() && a->second != b->second) return false;
  }
  return true;
}

}  // namespace rt
