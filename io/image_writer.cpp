#include "io/image_writer.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace rt {

uint8_t encode_srgb8(float linear) {
  const float c = std::isnan(linear) ? 0.0f : std::clamp(linear, 0.0f, 1.0f);
  const float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<uint8_t>(std::lround(encoded * 255.0f));
}

Rgb8Image encode_srgb8(const Image& image) {
  Rgb8Image out{image.width, image.height, {}};
  out.rgb.reserve(image.pixels.size() * 3);
  for (const Vec3& p : image.pixels) {
    out.rgb.push_back(encode_srgb8(p.x));
    out.rgb.push_back(encode_srgb8(p.y));
    out.rgb.push_back(encode_srgb8(p.z));
  }
  return out;
}

bool write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error) {
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  const std::string temp =
      (folder / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()))).string();
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) {
    error = "cannot create " + temp + ": " + std::strerror(errno);
    return false;
  }
  const bool written =
      std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  const int write_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) {
    error = "cannot write " + temp + ": " + std::strerror(written ? errno : write_errno);
    std::remove(temp.c_str());
    return false;
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    error = "cannot rename " + temp + " to " + path + ": " + std::strerror(errno);
    std::remove(temp.c_str());
    return false;
  }
  return true;
}

bool write_png(const std::string& path, const Image& image, std::string& error) {
  return write_png(path, encode_srgb8(image), error);
}

}  // namespace rt
