// rtcli's own denoiser: an edge-avoiding à-trous wavelet filter guided by the first hit's features
// and each pixel's variance (Dammertz et al. 2010, "Edge-Avoiding À-Trous Wavelet Transform";
// the variance-guided colour weight of Schied et al. 2017, SVGF), on demodulated radiance:
//  1. What the first thing met emits (a light's face, the background) is set aside, and the rest
//     divided by the albedo (floored), leaving the light arriving at each surface, which is
//     smooth where texture is not: texture detail and lights' edges never pass through the filter.
//  2. Three passes of a 5x5 B3-spline kernel with holes (steps 1, 2, 4: a 17-pixel-wide footprint
//     for 75 taps a pixel), each tap weighted by how alike the two pixels are: normals
//     (cosine^64), depth (against the depth's own slope), albedo, and luminance measured in
//     standard deviations of the noise. The variance goes through the same weights (squared), so
//     later, wider passes trust the colour more as it smooths.
//  3. Multiplied by the albedo again, and the emission added back.
// Pixels where the camera met nothing (the background) are filtered only among themselves.
// Tuned on the Cornell box at 16 samples per pixel against a converged reference: wider (four or
// five passes) or more trusting of colour (a luminance sigma of 16) blurred contact shadows into
// more error than the noise they took away (docs/rendering.md, "Denoising").
#pragma once

#include "core/denoise/denoiser.h"

namespace rt {

class FeatureFilter final : public Denoiser {
 public:
  static constexpr int kPasses = 3;
  static constexpr float kAlbedoFloor = 0.02f;    // below this (a mirror, black paint) nothing is demodulated
  static constexpr float kLuminanceSigma = 8.0f;  // luminance differences, in standard deviations
  static constexpr float kNormalPower = 64.0f;
  static constexpr float kDepthSigma = 1.0f;  // depth differences, in the slope's steps
  static constexpr float kAlbedoSigma = 0.1f;

  Image denoise(const DenoiseInput& input, unsigned threads) const override;
};

}  // namespace rt
