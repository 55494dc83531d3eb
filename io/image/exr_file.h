// OpenEXR images as rtcli writes and reads them (libopenexr, BSD-3-Clause): linear RGB in channels
// R, G, B, optional layers of data beside it (albedo.R/G/B, normal.X/Y/Z, depth.Z: what
// compositors and denoisers read), half or full float, ZIP-compressed, and string attributes
// (rtcli's metadata). The display window is the whole image; the data window is the part the file
// holds, so the tiles of a render split across machines are each a valid EXR of their own pixels.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/pixel_window.h"

namespace rt {

inline constexpr int kMaxExrChannels = 64;  // read_exr refuses a file of more

struct ExrLayer {
  std::string name;                   // "" for the colour (R, G, B); else the channels' prefix
  std::vector<std::string> channels;  // "R", "G", "B" / "X", "Y", "Z" / "Z"
  std::vector<float> values;          // window pixels, row-major, channels interleaved
};

struct ExrImage {
  int width = 0, height = 0;  // the whole image (display window)
  PixelWindow window;         // the pixels held (data window)
  std::vector<ExrLayer> layers;
  std::map<std::string, std::string> attributes;  // string attributes, e.g. "rtcli:scene_hash"
  bool full_float = false;  // read: every channel was 32-bit float (not half)

  const ExrLayer* layer(const std::string& name) const;
};

// Writes `image` (half floats unless `full_float`) through a temporary file renamed over `path`.
bool write_exr(const std::string& path, const ExrImage& image, bool full_float, std::string& error);

// Reads every channel as float, and the string attributes; nothing, with `error`, for a file that
// is not a complete OpenEXR image or holds more than `max_pixels` pixels.
std::optional<ExrImage> read_exr(const std::string& path, uint64_t max_pixels, std::string& error);

// Whether the file has a complete OpenEXR header and every line of pixels (a resumed render's
// test: a file cut short by a crash is not complete).
bool exr_is_complete(const std::string& path);

}  // namespace rt
