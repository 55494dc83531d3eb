// The layers an EXR output may hold beside the colour (--aov): each one's name, its channels, and
// which of the film's first-hit layers it holds (core/render/aovs.h: filled by the integrator in
// the same pass as the colour and averaged by the same pixel sampler, the depth the nearest), or
// the variance of each pixel's mean luminance (the path tracer's; 0 under Whitted). Together they
// are what a denoiser reads (denoise_input; rtcli merge --denoise reads them from tiles).
#pragma once

#include <string>
#include <vector>

#include "core/denoise/denoiser.h"
#include "core/render/film.h"
#include "io/image/exr_file.h"

namespace rt {

struct AovLayer {
  enum class Source { kAlbedo, kNormal, kDistance, kVariance, kEmission };
  const char* name;
  std::vector<std::string> channels;
  Source source;
};

inline const std::vector<AovLayer>& aov_layers() {
  static const std::vector<AovLayer> layers = {{"albedo", {"R", "G", "B"}, AovLayer::Source::kAlbedo},
                                               {"normal", {"X", "Y", "Z"}, AovLayer::Source::kNormal},
                                               {"depth", {"Z"}, AovLayer::Source::kDistance},
                                               {"variance", {"Y"}, AovLayer::Source::kVariance},
                                               {"emission", {"R", "G", "B"}, AovLayer::Source::kEmission}};
  return layers;
}

// The layer called `name`, or null.
inline const AovLayer* find_aov(const std::string& name) {
  for (const AovLayer& l : aov_layers())
    if (name == l.name) return &l;
  return nullptr;
}

// The layers a denoiser reads beside the colour: what a part of a render (--crop, --tile) written
// with --denoise holds, for rtcli merge --denoise.
inline const std::vector<std::string>& denoise_layers() {
  static const std::vector<std::string> names = {"albedo", "normal", "depth", "variance", "emission"};
  return names;
}

// What a denoiser reads of a film rendered with its first-hit layers.
inline DenoiseInput denoise_input(const Film& film) {
  return DenoiseInput{film.color, film.albedo, film.normal, film.emission, film.distance, film.variance};
}

// An RGB image as a layer called `name` ("": the colour).
inline ExrLayer color_layer(const Image& image, const std::string& name) {
  ExrLayer layer{name, {"R", "G", "B"}, {}};
  layer.values.reserve(image.pixels.size() * 3);
  for (const Vec3& p : image.pixels)
    for (int c = 0; c < 3; ++c) layer.values.push_back(p[c]);
  return layer;
}

// The layer's values from a film rendered with its first-hit layers (RenderView::aovs).
inline ExrLayer aov_layer(const Film& film, const AovLayer& aov) {
  ExrLayer layer{aov.name, aov.channels, {}};
  if (aov.source == AovLayer::Source::kDistance || aov.source == AovLayer::Source::kVariance) {
    layer.values = aov.source == AovLayer::Source::kDistance ? film.distance : film.variance;
    return layer;
  }
  const Image& image = aov.source == AovLayer::Source::kAlbedo   ? film.albedo
                       : aov.source == AovLayer::Source::kNormal ? film.normal
                                                                 : film.emission;
  layer.values.reserve(image.pixels.size() * 3);
  for (const Vec3& p : image.pixels)
    for (int c = 0; c < 3; ++c) layer.values.push_back(p[c]);
  return layer;
}

}  // namespace rt
