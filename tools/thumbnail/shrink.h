// Image shrinking for the gallery's thumbnails: an area average in linear light, so thin bright
// lines keep their brightness instead of darkening as an average of sRGB codes would.
#pragma once

#include "io/image/rgb8_image.h"

namespace rt {

// `image` scaled to `width` pixels across (the height in proportion, at least 1): each output
// pixel is the area-weighted mean of the input pixels it covers. An image no wider than `width`
// comes back unchanged.
Rgb8Image shrink_image(const Rgb8Image& image, int width);

}  // namespace rt
