// libjpeg's fatal errors jump back to compress() (io/image/jpeg_errors.h).
#include "io/image/jpeg_file.h"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "io/base/atomic_file.h"
#include "io/image/jpeg_errors.h"

namespace rt {
namespace {

// The libjpeg part alone, with no C++ object that longjmp could skip: false with `message` filled
// on an error. `buffer` is libjpeg's (grown as it writes; the caller frees it with free()).
bool compress(const Rgb8Image& image, int quality, unsigned char** buffer, unsigned long* size,
              char (&message)[JMSG_LENGTH_MAX]) {
  jpeg_compress_struct cinfo;
  JpegErrorManager errors;
  cinfo.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = rt_jpeg_jump_out;
  errors.message[0] = '\0';
  volatile bool ok = false;
  if (setjmp(errors.jump) == 0) {
    jpeg_create_compress(&cinfo);
    jpeg_mem_dest(&cinfo, buffer, size);
    cinfo.image_width = static_cast<JDIMENSION>(image.width);
    cinfo.image_height = static_cast<JDIMENSION>(image.height);
    cinfo.input_components = 3;
    cinfo.in_color_space = JCS_RGB;
    jpeg_set_defaults(&cinfo);
    jpeg_set_quality(&cinfo, quality, TRUE);
    jpeg_start_compress(&cinfo, TRUE);
    const size_t stride = static_cast<size_t>(image.width) * 3;
    while (cinfo.next_scanline < cinfo.image_height) {
      // libjpeg takes non-const rows but only reads them.
      JSAMPROW row = const_cast<JSAMPROW>(image.rgb.data() + cinfo.next_scanline * stride);
      jpeg_write_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_compress(&cinfo);
    ok = true;
  }
  jpeg_destroy_compress(&cinfo);
  std::memcpy(message, errors.message, sizeof message);
  return ok;
}

}  // namespace

std::vector<uint8_t> encode_jpeg(const Rgb8Image& image, int quality, std::string& error) {
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  char message[JMSG_LENGTH_MAX];
  std::vector<uint8_t> out;
  if (compress(image, quality, &buffer, &size, message)) out.assign(buffer, buffer + size);
  else error = std::string("could not encode the JPEG: ") + message;
  std::free(buffer);
  return out;
}

bool write_jpeg(const std::string& path, const Rgb8Image& image, std::string& error, int quality) {
  const std::vector<uint8_t> bytes = encode_jpeg(image, quality, error);
  if (bytes.empty()) return false;
  return write_file_atomically(path, bytes, error);
}

}  // namespace rt
