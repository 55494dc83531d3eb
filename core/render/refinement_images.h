// What --aa-debug writes beside the image: where adaptive anti-aliasing spent its rays, read
// from the film's refinement-depth channel.
#pragma once

#include <array>

#include "core/render/film.h"

namespace rt {

// Heat-map colour of each refinement depth 0..kMaxAdaptiveDepth (linear RGB): black, blue,
// green, orange, white. Fixed, so that maps of different renders compare (the legend:
// docs/command-line.md, --aa-debug).
inline constexpr std::array<Vec3, 5> kRefinementColors = {
    Vec3(0.0f), Vec3(0.01f, 0.06f, 0.8f), Vec3(0.02f, 0.5f, 0.03f), Vec3(1.0f, 0.35f, 0.0f), Vec3(1.0f)};

// What marks a refined pixel: pure green, which red objects (the anti-aliasing scene's poles), blue
// skies and grey floors do not hide.
inline constexpr Vec3 kRefinedMark{0.0f, 1.0f, 0.0f};

// The rendered colours, with every refined pixel (depth > 0) in kRefinedMark.
inline Image refined_pixels_marked(const Film& film) {
  Image out = film.color;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      if (film.depth[film.index(x, y)] > 0) out.at(x, y) = kRefinedMark;
  return out;
}

// Each pixel coloured by its refinement depth.
inline Image refinement_heat_map(const Film& film) {
  Image out(film.width(), film.height());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t d = std::min<size_t>(film.depth[film.index(x, y)], kRefinementColors.size() - 1);
      out.at(x, y) = kRefinementColors[d];
    }
  return out;
}

// Each pixel coloured by the camera samples it took (the path tracer's --samples-debug), out of
// `most`: the heat-map colours above spread evenly from 0 (black) to `most` (white), blended.
inline Image sample_count_heat_map(const Film& film, int most) {
  Image out(film.width(), film.height());
  const float top = static_cast<float>(kRefinementColors.size() - 1);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const float t =
          std::clamp(static_cast<float>(film.samples[film.index(x, y)]) / static_cast<float>(std::max(1, most)), 0.0f,
                     1.0f) *
          top;
      const size_t i = std::min(static_cast<size_t>(t), kRefinementColors.size() - 2);
      out.at(x, y) = glm::mix(kRefinementColors[i], kRefinementColors[i + 1], t - static_cast<float>(i));
    }
  return out;
}

}  // namespace rt
