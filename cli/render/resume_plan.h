// `render --resume FILE.exr`: the sums of an earlier render to add samples to, once the file is
// known to be the same render: the same scene files (their hash), the same settings but the
// samples a pixel (each that differs named), the same frame and the same part of the image.
// The render then goes on from each pixel's sums (core/render/sample_sums.h) to --spp samples in
// all, and its pixels are those of one render of them all, bit for bit (the earlier render's
// samples a pixel a multiple of 8, where a noise threshold is set: its checks fall every 8).
#pragma once

#include <optional>
#include <string>

#include "cli/frames/render_metadata.h"
#include "core/pixel_window.h"
#include "core/render/sample_sums.h"
#include "core/render_settings.h"

namespace rt {

// Nothing, after saying why (naming the file and what differs), when the file cannot be continued.
// `layers`: whether this render gathers the first hit's layers (then the file must hold their sums).
std::optional<SampleState> resume_state(const std::string& path, const RenderIdentity& identity, int frame,
                                        const PixelWindow& window, const RenderSettings& settings, bool layers);

}  // namespace rt
