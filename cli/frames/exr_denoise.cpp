#include "cli/frames/exr_denoise.h"

#include "core/denoise/denoiser.h"

namespace rt {
namespace {

// The layer's channels (named `names`, in that order: a file may hold them in any) as an image
// (three) or a list (one); false if the layer or a channel is not there.
bool read_layer(const ExrImage& exr, const std::string& name, const std::vector<std::string>& names, Image* image,
                std::vector<float>* values) {
  const ExrLayer* l = exr.layer(name);
  if (!l) return false;
  const size_t stride = l->channels.size();
  std::vector<size_t> at;
  for (const std::string& want : names) {
    size_t k = 0;
    while (k < stride && l->channels[k] != want) ++k;
    if (k == stride) return false;
    at.push_back(k);
  }
  const size_t pixels = static_cast<size_t>(exr.window.width()) * static_cast<size_t>(exr.window.height());
  if (values) {
    values->resize(pixels);
    for (size_t i = 0; i < pixels; ++i) (*values)[i] = l->values[stride * i + at[0]];
    return true;
  }
  *image = Image(exr.window.width(), exr.window.height());
  for (size_t i = 0; i < pixels; ++i)
    image->pixels[i] =
        Vec3(l->values[stride * i + at[0]], l->values[stride * i + at[1]], l->values[stride * i + at[2]]);
  return true;
}

}  // namespace

bool denoise_exr(ExrImage& exr, const std::string& denoiser, unsigned threads, std::string& error) {
  if (exr.window.x0 != 0 || exr.window.y0 != 0 || exr.window.width() != exr.width ||
      exr.window.height() != exr.height) {
    error = "--denoise needs the whole image; the tiles cover only part of it";
    return false;
  }
  Image color, albedo, normal, emission;
  std::vector<float> depth, variance;
  const std::vector<std::string> rgb = {"R", "G", "B"};
  if (!read_layer(exr, "", rgb, &color, nullptr) || !read_layer(exr, "albedo", rgb, &albedo, nullptr) ||
      !read_layer(exr, "normal", {"X", "Y", "Z"}, &normal, nullptr) ||
      !read_layer(exr, "emission", rgb, &emission, nullptr) || !read_layer(exr, "depth", {"Z"}, nullptr, &depth) ||
      !read_layer(exr, "variance", {"Y"}, nullptr, &variance)) {
    error =
        "--denoise reads the layers albedo, normal, depth, variance and emission, which the tiles do not all hold; "
        "render them with --denoise (or --aov albedo,normal,depth,variance,emission)";
    return false;
  }
  if (exr.layer("raw")) {
    error = "the tiles are already denoised (they hold a layer \"raw\")";
    return false;
  }
  const Image denoised =
      make_denoiser(denoiser)->denoise(DenoiseInput{color, albedo, normal, emission, depth, variance}, threads);
  for (ExrLayer& l : exr.layers)
    if (l.name.empty()) {
      ExrLayer raw = l;
      raw.name = "raw";
      const size_t stride = l.channels.size();
      for (size_t k = 0; k < stride; ++k)
        for (int c = 0; c < 3; ++c)
          if (l.channels[k] == rgb[static_cast<size_t>(c)])
            for (size_t i = 0; i < denoised.pixels.size(); ++i) l.values[stride * i + k] = denoised.pixels[i][c];
      exr.layers.push_back(std::move(raw));
      break;
    }
  return true;
}

}  // namespace rt
