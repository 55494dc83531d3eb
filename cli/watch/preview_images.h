// The pictures `rtcli watch`'s page asks for, made from the latest film when asked: the colour
// through the exposure and tone map the page chose (so that changing them needs no new render),
// or one of the first hit's layers, or where the samples went; as PNG, or as an EXR with every
// layer for saving.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cli/watch/preview_board.h"
#include "core/name_table.h"
#include "core/tone_map.h"
#include "io/image/rgb8_image.h"

namespace rt {

enum class PreviewLayer { kColor, kAlbedo, kNormal, kDepth, kRefinement };

inline constexpr NameEntry<PreviewLayer> kPreviewLayerEntries[] = {
    {"color", PreviewLayer::kColor, "the picture, through the exposure and tone map"},
    {"albedo", PreviewLayer::kAlbedo, "the first hit's diffuse colour"},
    {"normal", PreviewLayer::kNormal, "the first hit's shading normal, (n + 1) / 2 as RGB"},
    {"depth", PreviewLayer::kDepth, "the first hit's distance, white near, black far"},
    {"refinement", PreviewLayer::kRefinement,
     "where the samples went: the path tracer's samples a pixel (black none, white all), adaptive "
     "anti-aliasing's depth"}};
inline constexpr NameTable<PreviewLayer> kPreviewLayers{kPreviewLayerEntries};

// The layer as 8-bit RGB, at the film's size. `display` applies to the colour of a render that
// shows radiance (a debug view's values are shown as they are).
Rgb8Image preview_layer(const PreviewImage& image, PreviewLayer layer, const DisplayTransform& display);

// An OpenEXR file of the film: the colour and every layer, full floats. False, with `error`,
// if it could not be made.
bool preview_exr(const PreviewImage& image, std::vector<uint8_t>& bytes, std::string& error);

}  // namespace rt
