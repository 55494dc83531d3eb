// `rtcli merge`'s work: EXR tiles of one render (rtcli render --tile or --crop, -o NAME.exr) put
// back together. The tiles must come from the same scene files, settings, frame and rtcli (their
// metadata, cli/frames/render_metadata.h), hold the same layers, and cover the image exactly once; what
// is wrong is named: the tile missing (by its band, I/N) or the region no tile covers, the tiles
// that overlap, the setting that differs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/render_settings.h"
#include "io/image/exr_file.h"

namespace rt {

// The whole image, its metadata the tiles' with rtcli:crop the whole image and no rtcli:tile
// (what a render of the whole image writes); nothing, with every problem in `problems`. Each tile
// is read within `max_pixels` (and so max_pixels x kMaxExrValuesPerPixel values: the fuzzer's
// smaller limit lets it reach every channel x pixel product).
std::optional<ExrImage> merge_tiles(const std::vector<std::string>& paths, std::vector<std::string>& problems,
                                    uint64_t max_pixels = kMaxPixels);

}  // namespace rt
