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
// read_exr holds at most this many values (channels x pixels) a pixel of its limit: rtcli writes
// up to 36 (the colour, the raw colour, five layers, and a path-traced render's sample sums:
// cli/render/sample_state.h), and room is left for an alpha.
inline constexpr uint64_t kMaxExrValuesPerPixel = 40;

struct ExrLayer {
  std::string name;                   // "" for the colour (R, G, B); else the channels' prefix
  std::vector<std::string> channels;  // "R", "G", "B" / "X", "Y", "Z" / "Z"
  std::vector<float> values;          // window pixels, row-major, channels interleaved
  // Written as 32-bit floats even in a half-float file: data that must come back bit for bit (a
  // render's sample sums: cli/render/sample_state.h). Read: every channel was a float.
  bool exact = false;
};

struct ExrImage {
  int width = 0, height = 0;  // the whole image (display window)
  PixelWindow window;         // the pixels held (data window)
  std::vector<ExrLayer> layers;
  std::map<std::string, std::string> attributes;  // string attributes, e.g. "rtcli:scene_hash"
  bool full_float = false;                        // read: every channel was 32-bit float (not half)

  const ExrLayer* layer(const std::string& name) const;
};

// Writes `image` (half floats unless `full_float`) through a temporary file renamed over `path`.
bool write_exr(const std::string& path, const ExrImage& image, bool full_float, std::string& error);

// Reads every channel as float, and the string attributes; nothing, with `error` (naming the file),
// for a file that is not a regular file, not a complete OpenEXR image whose pixels decode, holds
// more than `max_pixels` pixels or more than max_pixels x kMaxExrValuesPerPixel values. The file is
// read once, through the bounded reader, and checked (io/image/exr_structure.h) before OpenEXR
// sees it.
std::optional<ExrImage> read_exr(const std::string& path, uint64_t max_pixels, std::string& error);

// The colour of any single-part scanline OpenEXR file in `bytes` (RGB, RGBA, luminance and chroma,
// half or float, any compression; OpenEXR's RGBA interface), as one layer "" of R, G, B over the
// whole image: environment images. Checked as read_exr checks, with 4 values a pixel.
std::optional<ExrImage> read_exr_rgb(const std::vector<unsigned char>& bytes, const std::string& name,
                                     uint64_t max_pixels, std::string& error);

}  // namespace rt
