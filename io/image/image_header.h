// What an image file is, from its first bytes, and how big, from its header, before any decoder
// runs. rtcli decodes PNG and JPEG only (docs/rendering.md, "Textures"): every other format is refused by
// name here, so a decoder never sees a file it was not meant for (Debian 12's stb_image 2.27
// over-reads 16-bit PNM files and loops forever on a truncated RLE Radiance .hdr). A JPEG's
// markers are walked to count its scans: a progressive JPEG's decoding costs a pass over the
// image per scan, and a small file can hold thousands.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

// The most scans a JPEG may have. Baseline JPEGs have one per colour component or one in all;
// libjpeg's and mozjpeg's progressive modes write 10 or fewer; 64 bounds the decoding work at 64
// passes over the image.
inline constexpr uint32_t kMaxJpegScans = 64;

enum class ImageFormat { kPng, kJpeg, kWebp };

struct ImageHeader {
  ImageFormat format = ImageFormat::kPng;
  uint32_t width = 0, height = 0;
  bool sixteen_bit = false;  // a PNG of 16 bits a sample
  uint64_t png_data = 0;     // a PNG's image data once inflated: filter bytes and scanlines, every pass
  uint32_t scans = 0;        // a JPEG's start-of-scan markers
};

// Calls visit(type, data, length, available) for each chunk of a PNG, in order, after its
// signature, up to IEND or the first chunk whose `length` exceeds the `available` bytes the file
// has left for it (that one comes with data == nullptr); stops early when visit returns false.
template <class Visit>
void for_each_png_chunk(const unsigned char* b, size_t size, const Visit& visit) {
  for (size_t pos = 8; pos <= size && size - pos >= 12;) {
    const uint32_t length =
        (uint32_t{b[pos]} << 24) | (uint32_t{b[pos + 1]} << 16) | (uint32_t{b[pos + 2]} << 8) | uint32_t{b[pos + 3]};
    const std::string_view type(reinterpret_cast<const char*>(b + pos + 4), 4);
    const size_t available = size - pos - 12;
    const bool fits = length <= available;
    if (!visit(type, fits ? b + pos + 8 : nullptr, length, available) || !fits || type == "IEND") return;
    pos += 12 + length;
  }
}

// The name of the format the bytes start like ("PNG", "GIF", "Radiance HDR", ...), or nullptr
// when they match none rtcli knows.
const char* image_format_name(const unsigned char* bytes, size_t size);

// The header of a PNG, JPEG or still WebP image (libwebp's own header parser): its size and, for a JPEG, its scans (at
// most kMaxJpegScans). Anything else, a truncated header, a zero size or an unsupported coding gives nullopt and
// `error` completing "cannot read FILE as an image: ...".
std::optional<ImageHeader> read_image_header(const unsigned char* bytes, size_t size, std::string& error);

}  // namespace rt
