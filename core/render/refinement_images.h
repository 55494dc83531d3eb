// What --aa-debug writes beside the image: where adaptive anti-aliasing spent its rays, read
// from the film's refinement-depth channel.
#pragma once

#include <array>

#include "core/render/film.h"

namespace rt {

// Heat-map colour of each refinement depth 0..kMaxAdaptiveDepth (linear RGB): black, blue,
// green, orange, white. Fixed, so that maps of different renders compare (README legend).
inline constexpr std::array<Vec3, 5> kRefinementColors = {
    Vec3(0.0f), Vec3(0.01f, 0.06f, 0.8f), Vec3(0.02f, 0.5f, 0.03f), Vec3(1.0f, 0.35f, 0.0f), Vec3(1.0f)};

// The rendered colours, with every refined pixel (depth > 0) pure red.
inline Image refined_pixels_in_red(const Film& film) {
  Image out = film.color;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      if (film.depth[film.index(x, y)] > 0) out.at(x, y) = Vec3(1.0f, 0.0f, 0.0f);
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

}  // namespace rt
