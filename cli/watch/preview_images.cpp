#include "cli/watch/preview_images.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "cli/render/aov_layers.h"
#include "core/render/refinement_images.h"
#include "io/base/input_file.h"
#include "io/image/exr_file.h"

namespace rt {
namespace {

// Data shown as it is: each value in [0, 1] to the nearest of 256 levels, no sRGB curve.
Rgb8Image data_image(const Image& image) {
  Rgb8Image out{image.width, image.height, {}};
  out.rgb.reserve(image.pixels.size() * 3);
  for (const Vec3& p : image.pixels)
    for (int c = 0; c < 3; ++c) {
      const float v = std::isfinite(p[c]) ? std::clamp(p[c], 0.0f, 1.0f) : 0.0f;
      out.rgb.push_back(static_cast<uint8_t>(std::lround(v * 255.0f)));
    }
  return out;
}

Image normal_colors(const Film& film) {
  Image out = film.normal;
  for (Vec3& n : out.pixels) n = n == Vec3(0.0f) ? Vec3(0.0f) : 0.5f * (n + Vec3(1.0f));
  return out;
}

// White at the nearest hit, black at the farthest (and where nothing was hit).
Image depth_shades(const Film& film) {
  float near = HUGE_VALF, far = 0.0f;
  for (const float d : film.distance)
    if (d < Aovs::kFarAway && std::isfinite(d)) {
      near = std::min(near, d);
      far = std::max(far, d);
    }
  Image out(film.width(), film.height());
  for (size_t i = 0; i < film.distance.size(); ++i) {
    const float d = film.distance[i];
    if (!(d < Aovs::kFarAway) || !std::isfinite(d)) continue;
    const float t = far > near ? (far - d) / (far - near) : 1.0f;
    out.pixels[i] = Vec3(0.1f + 0.9f * t);
  }
  return out;
}

}  // namespace

Rgb8Image preview_layer(const PreviewImage& image, PreviewLayer layer, const DisplayTransform& display) {
  const Film& film = image.film;
  switch (layer) {
    case PreviewLayer::kColor: return encode_srgb8(film.color, image.radiance ? display : DisplayTransform{});
    case PreviewLayer::kAlbedo: return encode_srgb8(film.albedo);
    case PreviewLayer::kNormal: return data_image(normal_colors(film));
    case PreviewLayer::kDepth: return data_image(depth_shades(film));
    case PreviewLayer::kRefinement:
      return encode_srgb8(image.path_traced ? sample_count_heat_map(film, image.target_samples)
                                            : refinement_heat_map(film));
  }
  return {};
}

bool preview_exr(const PreviewImage& image, std::vector<uint8_t>& bytes, std::string& error) {
  ExrImage exr;
  exr.width = image.film.width();
  exr.height = image.film.height();
  exr.window = PixelWindow::whole(exr.width, exr.height);
  exr.layers.push_back(color_layer(image.film.color, ""));
  for (const AovLayer& l : aov_layers()) exr.layers.push_back(aov_layer(image.film, l));
  exr.attributes["rtcli:samples"] = std::to_string(image.samples);
  // The EXR writer writes files (through a temporary and a rename): one in the temporary folder,
  // read back and removed.
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) {
    error = "no temporary folder: " + ec.message();
    return false;
  }
  std::string path = (dir / "rtcli-watch-XXXXXX").string();
  const int fd = ::mkstemp(path.data());
  if (fd < 0) {
    error = "could not make a temporary file in " + dir.string();
    return false;
  }
  ::close(fd);
  bool ok = write_exr(path, exr, true, error);
  if (ok) {
    auto read = read_input_bytes(path, uint64_t{4} << 30, error);
    ok = read.has_value();
    if (ok) bytes.assign(read->begin(), read->end());
  }
  std::filesystem::remove(path, ec);
  return ok;
}

}  // namespace rt
