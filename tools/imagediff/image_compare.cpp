#include "tools/imagediff/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace rt {

ImageDifference compare_images(const Rgb8Image& a, const Rgb8Image& b, int threshold) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size()) {
    d.same_size = false;
    return d;
  }
  long long sum = 0, sum_squares = 0;
  for (size_t i = 0; i < a.rgb.size(); i += 3) {
    int pixel_max = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int diff = std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c]));
      pixel_max = std::max(pixel_max, diff);
      sum += diff;
      sum_squares += diff * diff;
    }
    d.max_channel = std::max(d.max_channel, pixel_max);
    d.pixels_over += pixel_max > threshold;
  }
  if (!a.rgb.empty()) {
    d.mean_channel = static_cast<double>(sum) / static_cast<double>(a.rgb.size());
    d.rms_channel = std::sqrt(static_cast<double>(sum_squares) / static_cast<double>(a.rgb.size()));
  }
  return d;
}

Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b) {
  Rgb8Image out{a.width, a.height, ZeroedVector<uint8_t>(a.rgb.size())};
  for (size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i)
    out.rgb[i] = static_cast<uint8_t>(std::min(255, 8 * std::abs(int(a.rgb[i]) - int(b.rgb[i]))));
  return out;
}

}  // namespace rt
