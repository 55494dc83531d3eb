// 8-bit RGB images as files hold them: the encoded form of a rendered Image, and what golden
// tests and image diffs compare.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/image.h"
#include "core/tone_map.h"
#include "core/zeroed_vector.h"

namespace rt {

struct Rgb8Image {
  int width = 0;
  int height = 0;
  // Row-major, 3 bytes per pixel, row 0 at the top. Zeroed, not written, when made: the encoding
  // threads write every byte right after, and a 1920 x 1440 image's 8 MB zeroed on the main
  // thread first cost 3% of antialias.json's wall time.
  ZeroedVector<uint8_t> rgb;
};

// 8-bit output: each linear channel through the display transform (exposure and tone curve,
// core/tone_map.h; by default none), clamped to [0, 1] (NaN counts as 0), encoded with the sRGB
// transfer function and rounded to the nearest of 256 levels (srgb8 in core/color.h, an exact
// table). On up to `threads` threads, the same bytes.
Rgb8Image encode_srgb8(const Image& image, const DisplayTransform& display = {}, unsigned threads = 1);

// An 8-bit RGB image made a row at a time where it is used (the PNG encoder's bands), so that no
// whole copy is made: a 1920 x 1440 render's display encoding is 8 MB, every page of it a first
// touch. row(y, scratch) returns row y's width * 3 bytes: a row of an image read in place, or
// `scratch` (width * 3 bytes) filled. Called from several threads at once, for different rows;
// what it reads must outlive it.
struct Rgb8Rows {
  int width = 0;
  int height = 0;
  std::function<const uint8_t*(int y, uint8_t* scratch)> row;
};

// The rows of `image`, read in place.
Rgb8Rows rows_of(const Rgb8Image& image);
// encode_srgb8's rows, each encoded when asked for: the same bytes.
Rgb8Rows srgb8_rows(const Image& image, const DisplayTransform& display);

class ViewTransform;
// The same through an OpenColorIO view when one is given (io/image/view_transform.h): the linear
// radiance times 2^exposure, through the view (whose output is already display-encoded), rounded
// to 256 levels; the tone curve is not applied. Without a view: encode_srgb8.
Rgb8Image encode_display8(const Image& image, const DisplayTransform& display, const ViewTransform* view,
                          unsigned threads = 1);

}  // namespace rt
