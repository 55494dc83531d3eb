// The procedural patterns behind every texture the example scenes use (tools/textures/main.cpp
// writes them as PNG files). Each is a pure function of the point (x, y) in [0, 1)^2 of the image
// (y down), returning 8-bit-scale values in [0, 1]: sRGB-encoded colour for colour textures, plain
// data for height and normal maps. No randomness: the same program writes the same bytes.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "io/image/hdr_file.h"
#include "io/image/rgb8_image.h"

namespace rt::textures {

struct Pattern {
  std::string file;  // written as <folder>/<file>
  int width = 0, height = 0;
  Vec3 (*at)(float x, float y) = nullptr;
  const char* what = "";
};

// Every texture, in the order the tool writes them.
const std::vector<Pattern>& patterns();

// The pattern as an 8-bit image, each texel the average of 4 x 4 points so that edges are smooth.
Rgb8Image render_pattern(const Pattern& p);

// The test environment (scenes/textures/sky.hdr, written as a Radiance .hdr file): an
// equirectangular sky in linear radiance, 256 x 128, a blue gradient over a brown ground with a
// small, very bright sun (3 degrees across, radiance 400) at 35 degrees
// elevation, each texel the average of 4 x 4 points.
struct HdrPattern {
  std::string file;
  int width = 0, height = 0;
  const char* what = "";
};
const HdrPattern& sky_pattern();
HdrImage render_sky(const HdrPattern& p);

}  // namespace rt::textures
