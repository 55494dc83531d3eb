// Radiance RGBE images (.hdr, Greg Ward's format): the reader rtcli uses instead of stb_image's,
// which on Debian 12 (stb 2.27) loops forever on a truncated run-length-encoded file
// (CVE-2021-42715). Every count here is checked against what is left of the row and of the file
// before it is used, and every loop advances, so a hostile file ends in an error, never a hang or
// a read past the end. Flat and new-style run-length-encoded scanlines are read; the old
// run-length scheme (obsolete since 1991) is refused by name. The writer makes new-style RLE
// files (tools/textures writes the test sky with it).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/math.h"

namespace rt {

struct HdrImage {
  int width = 0, height = 0;
  std::vector<Vec3> texels;  // linear RGB, row-major, row 0 at the top
};

// `max_texels` is checked against the header before any pixel is read. On failure, nullopt
// and `error` says what was found.
std::optional<HdrImage> decode_hdr(std::span<const unsigned char> bytes, uint64_t max_texels, std::string& error);

// The image as a .hdr file's bytes ("#?RADIANCE", "-Y H +X W", RLE scanlines where 8 <= W < 32768).
std::vector<uint8_t> encode_hdr(const HdrImage& image);

// Whether the bytes start like a Radiance file ("#?").
inline bool looks_like_hdr(std::span<const unsigned char> b) { return b.size() >= 2 && b[0] == '#' && b[1] == '?'; }

}  // namespace rt
