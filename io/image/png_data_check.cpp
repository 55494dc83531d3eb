#include "io/image/png_data_check.h"

#include <zlib.h>

#include <array>

namespace rt {

bool png_data_fits(const unsigned char* b, size_t size, const ImageHeader& header, std::string& error) {
  const uint64_t allowed = header.png_data + header.png_data / 16 + 4096;
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return true;
  std::array<unsigned char, 1 << 16> out;
  uint64_t produced = 0;
  int status = Z_OK;
  // The IDAT chunks in order, as one stream (image_header.cpp has checked that they lie inside
  // the file). Output comes until inflate leaves room in the buffer: then it has taken the chunk.
  for_each_png_chunk(b, size, [&](std::string_view type, const unsigned char* bytes, uint32_t length, size_t) {
    if (type != "IDAT" || !bytes) return true;
    z.next_in = const_cast<unsigned char*>(bytes);
    z.avail_in = length;
    do {
      z.next_out = out.data();
      z.avail_out = static_cast<uInt>(out.size());
      status = inflate(&z, Z_NO_FLUSH);
      produced += out.size() - z.avail_out;
    } while (status == Z_OK && z.avail_out == 0 && produced <= allowed);
    if (status == Z_BUF_ERROR) status = Z_OK;  // the chunk is used up: on to the next
    return status == Z_OK && produced <= allowed;
  });
  inflateEnd(&z);
  if (produced <= allowed) return true;
  error = "expected a PNG whose image data inflates to the " + std::to_string(header.png_data) + " bytes its " +
          std::to_string(header.width) + " x " + std::to_string(header.height) +
          " pixels need, found more (a stream that would take memory without limit)";
  return false;
}

}  // namespace rt
