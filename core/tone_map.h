// From the renderer's linear radiance to what a display shows (render.exposure, render.tone_map):
// the radiance scaled by 2^exposure, then a curve that brings it into [0, 1] before the sRGB
// encoding (core/color.h). "clamp" cuts at 1 (the rule before tone mapping existed: bright areas
// go flat white); "filmic" rolls highlights off smoothly with Narkowicz's fit of the ACES
// reference rendering and output transforms ("ACES Filmic Tone Mapping Curve", 2016):
//   f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14),
// per channel, a display-linear value that is then sRGB-encoded. Nothing above 1 turns white
// abruptly (f(1) = 0.80, f(4) = 0.97; the fit reaches 1 at x = 7.24 and is clamped there), and
// mid grey is lifted a little (f(0.18) = 0.27). Every integrator that makes radiance goes through
// it (debug views do not: cli/render/render_command.cpp); the adaptive sampler compares displayed
// values, so it sees what the picture shows.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/name_table.h"

namespace rt {

enum class ToneMap { kClamp, kFilmic };

// The names render.tone_map and --tone-map take.
inline constexpr NameEntry<ToneMap> kToneMapEntries[] = {
    {"clamp", ToneMap::kClamp, "values above 1 cut to white"},
    {"filmic", ToneMap::kFilmic, "highlights rolled off (ACES fit)"}};
inline constexpr NameTable<ToneMap> kToneMaps{kToneMapEntries};

// render.exposure is limited to +-kMaxExposure stops (2^20: beyond any scene's need).
inline constexpr double kMaxExposure = 20.0;

struct DisplayTransform {
  float exposure = 0.0f;  // stops: the radiance is multiplied by 2^exposure
  ToneMap curve = ToneMap::kClamp;

  bool identity() const { return exposure == 0.0f && curve == ToneMap::kClamp; }

  // Narkowicz's ACES fit, clamped to [0, 1]; NaN and negative values give 0.
  static float filmic(float x) {
    if (!(x > 0.0f)) return 0.0f;
    const float y = x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f);
    return std::isfinite(y) ? std::min(y, 1.0f) : 1.0f;  // inf / inf for x = inf
  }

  // A display-linear value for the sRGB encoding; "clamp" leaves the cut at 1 to the encoding,
  // so with exposure 0 the bytes are exactly those of before.
  float apply(float linear) const {
    const float scaled = exposure == 0.0f ? linear : linear * std::exp2(exposure);
    return curve == ToneMap::kFilmic ? filmic(scaled) : scaled;
  }
  Vec3 apply(Vec3 linear) const { return Vec3(apply(linear.x), apply(linear.y), apply(linear.z)); }
};

}  // namespace rt
