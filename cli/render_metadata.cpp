#include "cli/render_metadata.h"

#include <cstdio>
#include <fstream>

namespace rt {
namespace {

// Exact and short: a float as C's hexadecimal form ("0x1.99999ap-4").
std::string exact(float v) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%a", static_cast<double>(v));
  return buffer;
}

}  // namespace

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

std::string settings_text(const RenderSettings& s, const RenderCommand& cmd, StereoMode stereo) {
  const AntialiasSettings& aa = s.antialias;
  std::string t;
  const auto add = [&](const std::string& key, const std::string& value) { t += key + "=" + value + ";"; };
  add("size", std::to_string(s.width) + "x" + std::to_string(s.height));
  add("seed", std::to_string(s.seed));
  add("integrator", s.integrator);
  add("max_depth", std::to_string(s.max_depth));
  add("antialias", aa.mode + "," + std::to_string(aa.samples) + "," + (aa.jitter ? "jitter" : "grid") + "," +
                       exact(aa.threshold) + "," + std::to_string(aa.max_depth) + "," +
                       (aa.positions == SamplePositions::kCorners ? "corners" : "centres"));
  add("glossy", s.glossy ? std::to_string(s.glossy_samples) : "off");
  add("shadow_samples", std::to_string(s.shadow_samples) + (s.scale_secondary_shadows ? ",scaled" : ",full"));
  add("detail", std::string(s.detail.textures ? "textures" : "no-textures") + "," +
                    (s.detail.bumps ? "bumps" : "no-bumps") + "," +
                    (s.detail.override_filter ? std::to_string(static_cast<int>(s.detail.filter)) : "own"));
  add("display", exact(s.display.exposure) + "," + tone_map_names()[static_cast<size_t>(s.display.curve)]);
  add("path", std::to_string(s.path.samples_per_pixel) + "," + exact(s.path.noise_threshold) + "," +
                  exact(s.path.clamp) + "," + std::to_string(static_cast<int>(s.path.strategy)));
  add("stereo", std::string(kStereoModeNames[static_cast<size_t>(stereo)]));
  add("camera", cmd.camera.value_or(""));
  add("background", cmd.background.value_or(""));
  add("ambient", cmd.ambient.value_or(""));
  add("animation", cmd.animation.value_or(""));
  add("fps", cmd.fps ? exact(*cmd.fps) : "");
  return t;
}

std::map<std::string, std::string> render_attributes(const RenderIdentity& id, int frame, const PixelWindow& window) {
  std::map<std::string, std::string> out = {
      {"rtcli:version", RTCLI_VERSION},
      {"rtcli:scene", id.scene},
      {"rtcli:scene_hash", id.scene_hash},
      {"rtcli:settings", id.settings},
      {"rtcli:settings_hash", hex64(fnv1a(id.settings.data(), id.settings.size()))},
      {"rtcli:frame", std::to_string(frame)},
      {"rtcli:crop", std::to_string(window.x0) + "," + std::to_string(window.y0) + "," + std::to_string(window.x1) +
                         "," + std::to_string(window.y1)},
      {"rtcli:seed", std::to_string(id.seed)},
      {"rtcli:exposure", exact(id.display.exposure)},
      {"rtcli:tone_map", tone_map_names()[static_cast<size_t>(id.display.curve)]},
      {"rtcli:fps", exact(id.fps)},
  };
  if (!id.tile.empty()) out["rtcli:tile"] = id.tile;
  return out;
}

bool same_render(const std::map<std::string, std::string>& file, const std::map<std::string, std::string>& expected) {
  for (const char* key : {"rtcli:scene_hash", "rtcli:settings_hash", "rtcli:frame", "rtcli:crop", "rtcli:tile"}) {
    const auto a = file.find(key), b = expected.find(key);
    if ((a == file.end()) != (b == expected.end())) return false;
    if (a != file.end() && a->second != b->second) return false;
  }
  return true;
}

}  // namespace rt
