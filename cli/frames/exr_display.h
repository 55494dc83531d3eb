// An rtcli EXR's colour as the image a PNG or GIF shows: its linear R, G, B through the display
// transform its metadata names (rtcli:exposure, rtcli:tone_map), as `rtcli render` would have
// encoded it. Used by merge and encode.
#pragma once

#include <optional>
#include <string>

#include "io/image/exr_file.h"
#include "io/image/rgb8_image.h"

namespace rt {

// Nothing, with `error`, when the file has no R, G, B or holds only part of its image.
std::optional<Rgb8Image> displayed(const ExrImage& image, const std::string& name, std::string& error);

}  // namespace rt
