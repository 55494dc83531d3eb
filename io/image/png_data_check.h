// A PNG's image data inflated once before decoding, counting the bytes: stb_image 2.27 inflates
// it into a buffer that grows to whatever the stream holds (up to 4 GiB) before it compares that
// with the image's size, so a small file of compressed zeros under a 1 x 1 header takes gigabytes.
// Here it is streamed through zlib into a small buffer and stopped once it exceeds what the
// header's size needs (ImageHeader::png_data).
#pragma once

#include <cstddef>
#include <string>

#include "io/image/image_header.h"

namespace rt {

// False, with the sizes in `error`, when the IDAT chunks inflate to more than the header's size
// needs (a little slack allowed). A stream that is broken is left to the decoder to report.
bool png_data_fits(const unsigned char* bytes, size_t size, const ImageHeader& header, std::string& error);

}  // namespace rt
