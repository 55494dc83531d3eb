// What a pixel of a progressive render has gathered so far (the path tracer's): its samples'
// sums, how many, and whether the noise threshold stopped it. A render continues from these
// exactly (render --resume keeps them in the EXR it writes: cli/render/sample_state.h), so that
// more samples added later give the bits one render of them all gives.
#pragma once

#include <vector>

#include "core/render/aovs.h"

namespace rt {

struct SampleSums {
  Vec3 sum{0.0f};
  Aovs layers;  // summed (the distance the nearest)
  double luminance = 0.0, luminance_squares = 0.0;
  int n = 0;
  bool stopped = false;  // by the noise threshold
};

// The sums of each pixel of a render's window, row-major.
using SampleState = std::vector<SampleSums>;

}  // namespace rt
