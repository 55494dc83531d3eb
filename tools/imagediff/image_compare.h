// Comparing two 8-bit images for golden tests: how far apart they are, and a picture of where.
#pragma once

#include <cstddef>

#include "io/image/rgb8_image.h"

namespace rt {

struct ImageDifference {
  bool same_size = true;
  int max_channel = 0;        // largest absolute difference of any channel, in levels of 255
  double mean_channel = 0.0;  // mean absolute channel difference
  double rms_channel = 0.0;   // root mean square channel difference
  size_t pixels_over = 0;     // pixels with any channel differing by more than the threshold
};

ImageDifference compare_images(const Rgb8Image& a, const Rgb8Image& b, int threshold);

// |a - b| per channel, amplified 8x, so that a difference of a few levels is visible.
Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b);

}  // namespace rt
