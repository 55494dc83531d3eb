#include <webp/decode.h>

#include "io/image/image_header.h"

#include <cstdio>
#include <cstring>

namespace rt {
namespace {

using std::to_string;

bool starts_with(const unsigned char* b, size_t size, const char* prefix, size_t n) {
  return size >= n && std::memcmp(b, prefix, n) == 0;
}

uint32_t be16(const unsigned char* p) { return (uint32_t{p[0]} << 8) | p[1]; }
uint32_t be32(const unsigned char* p) { return (be16(p) << 16) | be16(p + 2); }

std::string first_bytes(const unsigned char* b, size_t size) {
  std::string out;
  for (size_t i = 0; i < size && i < 4; ++i) {
    char hex[4];
    std::snprintf(hex, sizeof hex, "%s%02x", i ? " " : "", b[i]);
    out += hex;
  }
  return out.empty() ? "the file is empty" : "it starts with the bytes " + out;
}

// The PNG signature and its first chunk, IHDR (PNG 1.2, sections 3.1 and 4.1.1).
std::optional<ImageHeader> png_header(const unsigned char* b, size_t size, std::string& error) {
  if (size < 33 || be32(b + 8) != 13 || std::memcmp(b + 12, "IHDR", 4) != 0) {
    error = "expected a PNG file to begin with its 13-byte IHDR chunk, found " +
            (size < 33 ? "a file of " + to_string(size) + " bytes" : std::string("another chunk"));
    return std::nullopt;
  }
  ImageHeader h;
  h.format = ImageFormat::kPng;
  h.width = be32(b + 16);
  h.height = be32(b + 20);
  const unsigned depth = b[24], color = b[25];
  if (h.width == 0 || h.height == 0 || h.width > 0x7fffffffu || h.height > 0x7fffffffu) {
    error = "expected a PNG of 1 to 2^31 - 1 pixels a side, found " + to_string(h.width) + " x " + to_string(h.height);
    return std::nullopt;
  }
  const bool valid = (color == 0 && (depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16)) ||
                     (color == 3 && (depth == 1 || depth == 2 || depth == 4 || depth == 8)) ||
                     ((color == 2 || color == 4 || color == 6) && (depth == 8 || depth == 16));
  if (!valid || b[26] != 0 || b[27] != 0 || b[28] > 1) {
    error = "expected a PNG header PNG defines, found bit depth " + to_string(depth) + " with colour type " +
            to_string(color) + " (compression " + to_string(b[26]) + ", filter " + to_string(b[27]) + ", interlace " +
            to_string(b[28]) + ")";
    return std::nullopt;
  }
  h.sixteen_bit = depth == 16;
  // Filtered scanlines: a filter byte and the row's packed samples, per row of each of the seven
  // Adam7 passes when interlaced (PNG 1.2, sections 2.6 and 4.1.1).
  const uint64_t bits_per_pixel = uint64_t{depth} * (color == 2 ? 3 : color == 4 ? 2 : color == 6 ? 4 : 1);
  const auto scanlines = [&](uint64_t w, uint64_t rows) {
    return w == 0 ? 0 : rows * (1 + (w * bits_per_pixel + 7) / 8);
  };
  if (b[28] == 0) {
    h.png_data = scanlines(h.width, h.height);
  } else {
    static constexpr int kPass[7][4] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                                        {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};  // x0, y0, dx, dy
    for (const auto& p : kPass)
      h.png_data += scanlines((h.width + p[2] - 1 - p[0]) / p[2], (h.height + p[3] - 1 - p[1]) / p[3]);
  }
  // The chunks, as the decoder reads them. stb_image 2.27 grows its buffer for the image data to
  // what an IDAT chunk claims before reading it (a 273-byte file asked for 2 GiB), and hands memcpy
  // a null pointer for an empty IDAT chunk before any image data (undefined behaviour). Both found
  // by fuzzing; no encoder writes either.
  bool data = false;
  std::string problem;
  for_each_png_chunk(b, size, [&](std::string_view type, const unsigned char* bytes, uint32_t length, size_t left) {
    if (type != "IDAT") return true;
    if (length == 0 && !data) problem = "expected a PNG whose first IDAT chunk holds image data, found an empty one";
    else if (!bytes)
      problem = "expected a PNG whose IDAT chunks lie inside the file, found one of " + to_string(length) +
                " bytes with " + to_string(left) + " left: the file is truncated";
    data = true;
    return problem.empty();
  });
  if (!problem.empty()) {
    error = problem;
    return std::nullopt;
  }
  return h;
}

// A define-Huffman-table segment, its tables read as stb_image reads them (by their own counts,
// not the segment's length). stb_image 2.27 builds each table before checking it: more than 256
// codes in one writes past its arrays (fixed in 2.28, not in Debian 12's package). False for such
// a table.
bool huffman_tables_fit(const unsigned char* b, size_t size, size_t pos) {
  const auto byte = [&](size_t i) -> unsigned { return i < size ? b[i] : 0; };  // stb reads 0 past the end
  int64_t left = static_cast<int64_t>(be16(b + pos)) - 2;
  size_t p = pos + 2;
  while (left > 0) {
    const unsigned q = byte(p++);
    if ((q >> 4) > 1 || (q & 15) > 3) return true;  // refused by stb_image before it builds anything
    unsigned codes = 0;
    for (int i = 0; i < 16; ++i) codes += byte(p++);
    if (codes > 256) return false;
    p += codes;
    left -= 17 + static_cast<int64_t>(codes);
  }
  return true;
}

bool is_start_of_frame(unsigned m) { return m >= 0xc0 && m <= 0xcf && m != 0xc4 && m != 0xc8 && m != 0xcc; }

// Walks a JPEG's markers (ITU T.81, Annex B): the frame header gives the size and the coding,
// and every start of scan is counted. Entropy-coded data is skipped to the next marker (a 0xff
// not followed by 0x00 stuffing or a restart marker).
std::optional<ImageHeader> jpeg_header(const unsigned char* b, size_t size, std::string& error) {
  ImageHeader h;
  h.format = ImageFormat::kJpeg;
  bool frame = false;
  size_t pos = 2;
  while (pos < size) {
    if (b[pos] != 0xff) {  // bytes between segments: decoders skip them, and so does this walk
      ++pos;
      continue;
    }
    while (pos < size && b[pos] == 0xff) ++pos;  // fill bytes
    if (pos >= size) break;
    const unsigned marker = b[pos++];
    if (marker == 0xd9) break;  // end of image
    if (marker == 0x00 || marker == 0x01 || marker == 0xd8 || (marker >= 0xd0 && marker <= 0xd7))
      continue;  // no length
    if (pos + 2 > size) break;
    const size_t length = be16(b + pos);
    if (marker == 0xc4 && !huffman_tables_fit(b, size, pos)) {  // even in a truncated segment
      error = "expected Huffman tables of at most 256 codes each in a JPEG, found one with more";
      return std::nullopt;
    }
    if (length < 2 || length > size - pos) break;  // truncated: the decoder says so
    if (is_start_of_frame(marker) && !frame) {
      if (marker != 0xc0 && marker != 0xc1 && marker != 0xc2) {
        error = "expected a baseline or progressive JPEG (Huffman coding), found one coded as " +
                std::string(marker == 0xc3 || marker == 0xc7 || marker == 0xcb || marker == 0xcf ? "lossless"
                            : marker >= 0xc9                                                     ? "arithmetic"
                                                                                                 : "hierarchical") +
                ", which rtcli cannot decode";
        return std::nullopt;
      }
      if (length < 8) break;
      h.height = be16(b + pos + 3);
      h.width = be16(b + pos + 5);
      if (b[pos + 2] != 8 || h.width == 0 || h.height == 0) {
        error = "expected a JPEG of 8-bit samples and a height in its frame header, found " + to_string(b[pos + 2]) +
                "-bit samples, " + to_string(h.width) + " x " + to_string(h.height) + " pixels";
        return std::nullopt;
      }
      frame = true;
    }
    pos += length;
    if (marker != 0xda) continue;
    if (++h.scans > kMaxJpegScans) {
      error = "expected a JPEG of at most " + to_string(kMaxJpegScans) +
              " scans, found more (each scan costs a pass over the image; common encoders write 10 or fewer)";
      return std::nullopt;
    }
    while (pos + 1 < size) {
      const auto* next = static_cast<const unsigned char*>(std::memchr(b + pos, 0xff, size - pos - 1));
      if (!next) {
        pos = size;
        break;
      }
      pos = static_cast<size_t>(next - b);
      const unsigned after = b[pos + 1];
      if (after != 0x00 && !(after >= 0xd0 && after <= 0xd7)) break;
      pos += 2;
    }
  }
  if (!frame) {
    error = "expected a JPEG frame header (SOF marker) with the image's size, found none";
    return std::nullopt;
  }
  return h;
}

}  // namespace

const char* image_format_name(const unsigned char* b, size_t size) {
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const auto is = [&](const char* prefix, size_t n) { return starts_with(b, size, prefix, n); };
  if (size >= 8 && std::memcmp(b, kPng, 8) == 0) return "PNG";
  if (is("\xff\xd8\xff", 3)) return "JPEG";
  if (is("GIF87a", 6) || is("GIF89a", 6)) return "GIF";
  if (is("BM", 2)) return "BMP";
  if (is("8BPS", 4)) return "Photoshop (PSD)";
  if (is("#?RADIANCE", 10) || is("#?RGBE", 6)) return "Radiance HDR";
  if (size >= 3 && b[0] == 'P' && ((b[1] >= '1' && b[1] <= '7') || b[1] == 'F' || b[1] == 'f') &&
      (b[2] == ' ' || b[2] == '\n' || b[2] == '\r' || b[2] == '\t'))
    return "Netpbm (PNM)";
  if (is("\x53\x80\xf6\x34", 4)) return "Softimage PIC";
  if (is("II*\0", 4) || is("MM\0*", 4)) return "TIFF";
  if (is("RIFF", 4) && size >= 12 && std::memcmp(b + 8, "WEBP", 4) == 0) return "WebP";
  if (is("\x76\x2f\x31\x01", 4)) return "OpenEXR";
  if (is("qoif", 4)) return "QOI";
  if (is("\0\0\0\x0cjP  \r\n\x87\n", 12) || is("\xff\x4f\xff\x51", 4)) return "JPEG 2000";
  if (is("\xabKTX ", 5)) return "KTX";
  if (is("DDS ", 4)) return "DirectDraw Surface (DDS)";
  if (size >= 12 && std::memcmp(b + 4, "ftyp", 4) == 0) return "ISO media (AVIF or HEIF)";
  if (size >= 18 && std::memcmp(b + size - 18, "TRUEVISION-XFILE.\0", 18) == 0) return "Truevision TGA";
  return nullptr;
}

// A WebP's size from its RIFF header, by libwebp's parser (which reads no pixel data). Animated
// WebP is refused: a texture is one picture.
std::optional<ImageHeader> webp_header(const unsigned char* b, size_t size, std::string& error) {
  WebPBitstreamFeatures features;
  if (WebPGetFeatures(b, size, &features) != VP8_STATUS_OK || features.width <= 0 || features.height <= 0) {
    error = "expected a WebP image whose header can be read, found a damaged or truncated one";
    return std::nullopt;
  }
  if (features.has_animation) {
    error = "expected a still WebP image, found an animated one";
    return std::nullopt;
  }
  ImageHeader h;
  h.format = ImageFormat::kWebp;
  h.width = static_cast<uint32_t>(features.width);
  h.height = static_cast<uint32_t>(features.height);
  return h;
}

std::optional<ImageHeader> read_image_header(const unsigned char* bytes, size_t size, std::string& error) {
  const char* format = image_format_name(bytes, size);
  if (format && std::strcmp(format, "PNG") == 0) return png_header(bytes, size, error);
  if (format && std::strcmp(format, "JPEG") == 0) return jpeg_header(bytes, size, error);
  if (format && std::strcmp(format, "WebP") == 0) return webp_header(bytes, size, error);
  error = format ? std::string("expected a PNG, JPEG or WebP image, found a") +
                       (std::strchr("AEIOU", format[0]) ? "n " : " ") + format + " image"
                 : "expected a PNG, JPEG or WebP image, found neither (" + first_bytes(bytes, size) + ")";
  return std::nullopt;
}

}  // namespace rt
