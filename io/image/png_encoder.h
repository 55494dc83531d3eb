// PNG encoding with zlib, fast enough that writing the image never costs as much as rendering
// it: rows filtered with "Sub", deflated at zlib's fastest level, in bands of rows compressed on
// several threads and joined into one zlib stream (as pigz does). The band size is fixed, so the
// bytes of the file do not depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image/rgb8_image.h"

namespace rt {

// The complete PNG file (8-bit RGB, no interlacing). Empty only if zlib fails (out of memory).
std::vector<uint8_t> encode_png(const Rgb8Image& image, unsigned threads = 1);
// The same from rows made as the bands need them (a render's display encoding, io/image/rgb8_image.h).
std::vector<uint8_t> encode_png(const Rgb8Rows& rows, unsigned threads = 1);

}  // namespace rt
