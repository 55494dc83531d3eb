#include "io/image/hdr_file.h"

#include <cmath>
#include <cstring>

namespace rt {
namespace {

// A byte cursor that never reads past the end.
struct Cursor {
  std::span<const unsigned char> bytes;
  size_t at = 0;

  size_t left() const { return bytes.size() - at; }
  // The next line without its '\n'; false at the end of the data or past `max` characters.
  bool line(std::string& out, size_t max = 4096) {
    out.clear();
    while (at < bytes.size()) {
      const char c = static_cast<char>(bytes[at++]);
      if (c == '\n') return true;
      if (out.size() >= max) return false;
      out.push_back(c);
    }
    return false;
  }
};

Vec3 rgbe_to_float(const unsigned char* p) {
  if (p[3] == 0) return Vec3(0.0f);
  const float f = std::ldexp(1.0f, static_cast<int>(p[3]) - (128 + 8));
  return Vec3((p[0] + 0.5f) * f, (p[1] + 0.5f) * f, (p[2] + 0.5f) * f);
}

// One scanline of `width` RGBE pixels into `row` (4 bytes each).
bool read_scanline(Cursor& c, int width, std::vector<unsigned char>& row, std::string& error) {
  const size_t w = static_cast<size_t>(width);
  if (c.left() < 4) {
    error = "the pixel data ends early";
    return false;
  }
  const unsigned char* p = c.bytes.data() + c.at;
  const bool rle = width >= 8 && width < 32768 && p[0] == 2 && p[1] == 2 && (p[2] & 0x80) == 0;
  if (!rle) {
    if (p[0] == 1 && p[1] == 1 && p[2] == 1) {
      error =
          "it uses the old run-length encoding, which rtcli does not read; save it again (any current tool writes the "
          "new one)";
      return false;
    }
    if (c.left() < 4 * w) {
      error = "the pixel data ends early";
      return false;
    }
    std::memcpy(row.data(), p, 4 * w);
    c.at += 4 * w;
    return true;
  }
  const size_t line_width = (static_cast<size_t>(p[2]) << 8) | p[3];
  if (line_width != w) {
    error = "a scanline says its width is " + std::to_string(line_width) + ", the header " + std::to_string(w);
    return false;
  }
  c.at += 4;
  // Each channel in turn: runs (count > 128: the next byte count - 128 times) and literals
  // (count <= 128: that many bytes); a count of 0 or one past the row's end is an error.
  for (size_t channel = 0; channel < 4; ++channel) {
    size_t x = 0;
    while (x < w) {
      if (c.left() < 1) {
        error = "the pixel data ends early";
        return false;
      }
      size_t count = c.bytes[c.at++];
      const bool run = count > 128;
      if (run) count -= 128;
      if (count == 0 || count > w - x) {
        error = "a run-length count of " + std::to_string(count) + " overruns its scanline";
        return false;
      }
      if (c.left() < (run ? 1 : count)) {
        error = "the pixel data ends early";
        return false;
      }
      for (size_t k = 0; k < count; ++k) row[4 * (x + k) + channel] = c.bytes[run ? c.at : c.at + k];
      c.at += run ? 1 : count;
      x += count;
    }
  }
  return true;
}

}  // namespace

std::optional<HdrImage> decode_hdr(std::span<const unsigned char> bytes, uint64_t max_texels, std::string& error) {
  Cursor c{bytes};
  std::string line;
  if (!c.line(line) || (line.rfind("#?RADIANCE", 0) != 0 && line.rfind("#?RGBE", 0) != 0)) {
    error = "expected a Radiance .hdr file (a first line \"#?RADIANCE\")";
    return std::nullopt;
  }
  // Header lines up to an empty one; only the format matters.
  for (int lines = 0;; ++lines) {
    if (!c.line(line) || lines > 1000) {
      error = "the header does not end (no empty line before the resolution)";
      return std::nullopt;
    }
    if (line.empty()) break;
    if (line.rfind("FORMAT=", 0) == 0 && line != "FORMAT=32-bit_rle_rgbe") {
      error = "expected FORMAT=32-bit_rle_rgbe, found " + line;
      return std::nullopt;
    }
  }
  if (!c.line(line, 64)) {
    error = "the resolution line is missing";
    return std::nullopt;
  }
  char y_axis[3] = {}, x_axis[3] = {};
  long height = 0, width = 0;
  char tail = 0;
  if (std::sscanf(line.c_str(), "%2s %ld %2s %ld %c", y_axis, &height, x_axis, &width, &tail) != 4 ||
      std::strcmp(y_axis, "-Y") != 0 || std::strcmp(x_axis, "+X") != 0) {
    error = "expected the resolution as \"-Y HEIGHT +X WIDTH\" (the standard orientation), found \"" + line + "\"";
    return std::nullopt;
  }
  if (width < 1 || height < 1 || width > 65535 || height > 65535 ||
      static_cast<uint64_t>(width) * static_cast<uint64_t>(height) > max_texels) {
    error = "expected at most " + std::to_string(max_texels) + " texels, found " + std::to_string(width) + " x " +
            std::to_string(height);
    return std::nullopt;
  }
  // The fewest bytes that many scanlines can be written in (a run-length line: a 4-byte header and
  // a run of at most 127 bytes in 2, for each of 4 channels; else 4 bytes a pixel), checked before
  // the texels are allocated: a header promising 8192 x 4096 with no pixels took 400 MB.
  const bool rle_width = width >= 8 && width < 32768;
  const uint64_t min_line =
      rle_width ? 4 + 4 * 2 * ((static_cast<uint64_t>(width) + 126) / 127) : 4 * static_cast<uint64_t>(width);
  if (c.left() / min_line < static_cast<uint64_t>(height)) {
    error = "the header promises " + std::to_string(width) + " x " + std::to_string(height) +
            " texels, which take at least " + std::to_string(min_line * static_cast<uint64_t>(height)) +
            " bytes, and " + std::to_string(c.left()) + " follow it (cut short?)";
    return std::nullopt;
  }
  HdrImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.texels.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
  std::vector<unsigned char> row(4 * static_cast<size_t>(width));
  for (int y = 0; y < image.height; ++y) {
    if (!read_scanline(c, image.width, row, error)) {
      error += " (scanline " + std::to_string(y + 1) + " of " + std::to_string(image.height) + ")";
      return std::nullopt;
    }
    for (int x = 0; x < image.width; ++x)
      image.texels[static_cast<size_t>(y) * image.width + x] = rgbe_to_float(&row[4 * static_cast<size_t>(x)]);
  }
  return image;
}

namespace {

void to_rgbe(Vec3 v, unsigned char* out) {
  const float m = std::max({v.x, v.y, v.z});
  if (!(m > 1e-32f) || !std::isfinite(m)) {
    std::memset(out, 0, 4);
    return;
  }
  int e;
  const float scale = std::frexp(m, &e) * 256.0f / m;
  out[0] = static_cast<unsigned char>(std::clamp(v.x * scale, 0.0f, 255.0f));
  out[1] = static_cast<unsigned char>(std::clamp(v.y * scale, 0.0f, 255.0f));
  out[2] = static_cast<unsigned char>(std::clamp(v.z * scale, 0.0f, 255.0f));
  out[3] = static_cast<unsigned char>(std::clamp(e + 128, 0, 255));
}

}  // namespace

std::vector<uint8_t> encode_hdr(const HdrImage& image) {
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(image.height) + " +X " +
                             std::to_string(image.width) + "\n";
  std::vector<uint8_t> out(header.begin(), header.end());
  const size_t w = static_cast<size_t>(image.width);
  std::vector<unsigned char> row(4 * w);
  const bool rle = image.width >= 8 && image.width < 32768;
  for (int y = 0; y < image.height; ++y) {
    for (size_t x = 0; x < w; ++x) to_rgbe(image.texels[static_cast<size_t>(y) * w + x], &row[4 * x]);
    if (!rle) {
      out.insert(out.end(), row.begin(), row.end());
      continue;
    }
    out.insert(out.end(), {2, 2, static_cast<uint8_t>(w >> 8), static_cast<uint8_t>(w & 0xff)});
    for (size_t channel = 0; channel < 4; ++channel) {
      size_t x = 0;
      while (x < w) {
        // A run of at least 3 equal bytes becomes a run; otherwise literals up to the next run.
        size_t run = 1;
        while (x + run < w && run < 127 && row[4 * (x + run) + channel] == row[4 * x + channel]) ++run;
        if (run >= 3) {
          out.push_back(static_cast<uint8_t>(128 + run));
          out.push_back(row[4 * x + channel]);
          x += run;
          continue;
        }
        size_t n = 0;
        while (x + n < w && n < 128) {
          size_t ahead = 1;
          while (x + n + ahead < w && ahead < 3 && row[4 * (x + n + ahead) + channel] == row[4 * (x + n) + channel])
            ++ahead;
          if (ahead >= 3) break;
          ++n;
        }
        if (n == 0) n = 1;
        out.push_back(static_cast<uint8_t>(n));
        for (size_t k = 0; k < n; ++k) out.push_back(row[4 * (x + k) + channel]);
        x += n;
      }
    }
  }
  return out;
}

}  // namespace rt
