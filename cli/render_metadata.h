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

#include "cli/render_command.h"
#include "core/pixel_window.h"
#include "core/render_settings.h"
#include "core/stereo.h"

namespace rt {

// FNV-1a, 64 bits, continuing from `hash` (a checksum for telling renders apart, not a secure hash).
inline constexpr uint64_t kFnvBasis = 0xcbf29ce484222325ull;
uint64_t fnv1a(const void* data, size_t size, uint64_t hash = kFnvBasis);
std::string hex64(uint64_t value);

// The hash of the files' contents, in order; "" if one cannot be read.
std::string hash_files(const std::vector<std::string>& paths);

// The settings text (see above): the render settings and the command's choices that change the
// pixels but are not render settings (camera, background, ambient, animation, fps, stereo).
std::string settings_text(const RenderSettings& settings, const RenderCommand& cmd, StereoMode stereo);

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
