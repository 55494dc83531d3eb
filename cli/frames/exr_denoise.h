// Denoising a merged render (rtcli merge --denoise): the colour of an EXR whose layers hold what a
// denoiser reads (a --crop or --tile render with --denoise writes them: cli/render/aov_layers.h),
// denoised in place, the raw colour kept as layer "raw". The same denoiser on the same floats as
// a whole render's, so tiles written with --exr-float merge into the whole render's image.
#pragma once

#include <string>

#include "io/image/exr_file.h"

namespace rt {

// False, with `error`, when a layer is missing or the image is not whole.
bool denoise_exr(ExrImage& image, const std::string& denoiser, unsigned threads, std::string& error);

}  // namespace rt
