// What an EXR file from `rtcli render` says about where its pixels came from, so that `rtcli
// merge` can refuse tiles of different renders and name what differs (docs/cluster.md):
//   rtcli:version        the rtcli that rendered it
//   rtcli:scene          the scene file as given on the command line
//   rtcli:scene_hash     FNV-1a 64 of every file the scene read (scene, glTF, buffers, images), in order
//   rtcli:settings       every setting that shapes the pixels, as text (seed included; not threads,
//                        tile size, outputs or the part rendered)
//   rtcli:settings_hash  FNV-1a 64 of that text
//   rtcli:frame, rtcli:crop ("x0,y0,x1,y1"), rtcli:seed, rtcli:exposure, rtcli:tone_map, rtcli:fps
//   rtcli:tile           "I/N" for --tile's band I of N (absent otherwise, and in a merged image)
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/pixel_window.h"
#include "core/render_settings.h"
#include "core/stereo.h"

namespace rt {

// The keys, each written by render_attributes and read by name through these constants only.
namespace exr_key {
inline constexpr const char* kVersion = "rtcli:version";
inline constexpr const char* kScene = "rtcli:scene";
inline constexpr const char* kSceneHash = "rtcli:scene_hash";
inline constexpr const char* kSettings = "rtcli:settings";
inline constexpr const char* kSettingsHash = "rtcli:settings_hash";
inline constexpr const char* kFrame = "rtcli:frame";
inline constexpr const char* kCrop = "rtcli:crop";
inline constexpr const char* kSeed = "rtcli:seed";
inline constexpr const char* kExposure = "rtcli:exposure";
inline constexpr const char* kToneMap = "rtcli:tone_map";
inline constexpr const char* kFps = "rtcli:fps";
inline constexpr const char* kTile = "rtcli:tile";
}  // namespace exr_key

// FNV-1a, 64 bits, continuing from `hash` (a checksum for telling renders apart, not a secure hash).
inline constexpr uint64_t kFnvBasis = 0xcbf29ce484222325ull;
uint64_t fnv1a(const void* data, size_t size, uint64_t hash = kFnvBasis);
std::string hex64(uint64_t value);

// The hash of the files' contents, in order; "" if one cannot be read.
std::string hash_files(const std::vector<std::string>& paths);

// A float exact and short, as C's hexadecimal form ("0x1.99999ap-4"): how the metadata and the
// settings text (cli/render/settings_text.h) write numbers.
std::string float_text(float v);

struct RenderIdentity {
  std::string scene;
  std::string scene_hash;
  std::string settings;  // settings_text
  uint64_t seed = 0;
  DisplayTransform display;
  float fps = 24.0f;  // the scene's frame rate, for rtcli encode
  std::string tile;   // "I/N", or empty
};

std::map<std::string, std::string> render_attributes(const RenderIdentity& id, int frame, const PixelWindow& window);

// Whether a file's attributes say it holds the same pixels as `expected` (render_attributes):
// the same scene and settings hashes, frame, crop and tile.
bool same_render(const std::map<std::string, std::string>& file, const std::map<std::string, std::string>& expected);

}  // namespace rt
