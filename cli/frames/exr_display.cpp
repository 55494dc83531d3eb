#include "cli/frames/exr_display.h"

#include <algorithm>
#include <cstdlib>

#include "cli/frames/render_metadata.h"
#include "core/image.h"

namespace rt {

std::optional<Rgb8Image> displayed(const ExrImage& image, const std::string& name, std::string& error) {
  const ExrLayer* color = image.layer("");
  if (!color || color->channels.size() < 3 || color->channels[0] != "R" || color->channels[1] != "G" ||
      color->channels[2] != "B") {
    error = name + ": expected the colour channels R, G, B";
    return std::nullopt;
  }
  if (image.window != PixelWindow::whole(image.width, image.height)) {
    error = name + ": holds part of its image (a tile); put the tiles together with rtcli merge first";
    return std::nullopt;
  }
  DisplayTransform display;
  if (const auto it = image.attributes.find(exr_key::kExposure); it != image.attributes.end())
    display.exposure = std::strtof(it->second.c_str(), nullptr);
  if (const auto it = image.attributes.find(exr_key::kToneMap); it != image.attributes.end()) {
    if (const auto curve = kToneMaps.parse(it->second)) display.curve = *curve;
  }
  Image linear(image.width, image.height);
  const size_t n = color->channels.size();
  for (size_t i = 0; i < linear.pixels.size(); ++i)
    linear.pixels[i] = Vec3(color->values[i * n], color->values[i * n + 1], color->values[i * n + 2]);
  return encode_srgb8(linear, display);
}

}  // namespace rt
