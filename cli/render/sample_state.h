// A path-traced render's sample sums (core/render/sample_sums.h) as EXR layers, so that
// `render --resume FILE.exr` can add samples to it and give the bits one render of them all
// gives. Every EXR of the path tracer holds them, as 32-bit floats whatever the colour's:
//   state.sum        R, G, B   the radiance summed (the colour is it over the count)
//   state.count      N         samples taken; negative where the noise threshold stopped the pixel
//   state.luminance  A-D       the double sum of the samples' luminances, 16 bits a channel
//   state.squares    A-D       the same for their squares (the noise threshold's variance)
//   state.albedo, state.normal, state.emission (3 channels), state.distance (Z): the first hit's
//                              layers summed, when the render gathered them (--aov, --denoise)
// 12 values a pixel (22 with the layers): 48 (88) bytes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/render/sample_sums.h"
#include "io/image/exr_file.h"

namespace rt {

// The layers of `state`; with the first hit's layers when `layers`.
std::vector<ExrLayer> sample_state_layers(const SampleState& state, bool layers);

// Whether the image holds a render's sample sums (its state.count layer).
bool has_sample_state(const ExrImage& image);

// The sums an EXR holds, one per pixel of its window, checked (whole counts of at most
// `most_samples`, finite non-negative sums, 16-bit parts); nothing, with `error`, if they are
// missing, broken, or lack the first hit's layers when `layers` are needed.
std::optional<SampleState> read_sample_state(const ExrImage& image, bool layers, int most_samples, std::string& error);

}  // namespace rt
