// JPEG through libjpeg-turbo (Debian's libjpeg62-turbo-dev). libjpeg reports a fatal error by
// calling error_exit, which must not return: it jumps back here with longjmp. So no object with a
// destructor is made between setjmp and the last libjpeg call, and the buffers are allocated
// before setjmp. Warnings about data libjpeg recovers from ("premature end of data segment") are
// not printed: the image decodes, with grey where the data was missing.
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include "io/image/jpeg_errors.h"
#include "io/image/png_jpeg_decoder.h"

namespace rt {
namespace {

extern "C" void stay_quiet(j_common_ptr, int) {}

// The libjpeg part alone, with no C++ object that longjmp could skip: false with `message` filled
// on an error; `size_differs` when libjpeg reads another size than the header's.
bool decompress(const unsigned char* bytes, size_t size, const ImageHeader& header, size_t out, unsigned char* pixels,
                unsigned char* row, bool* size_differs, char (&message)[JMSG_LENGTH_MAX]) {
  const size_t width = header.width;
  jpeg_decompress_struct cinfo;
  JpegErrorManager errors;
  cinfo.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = rt_jpeg_jump_out;
  errors.base.emit_message = stay_quiet;
  errors.message[0] = '\0';
  volatile bool ok = false;
  if (setjmp(errors.jump) == 0) {
    jpeg_create_decompress(&cinfo);
    jpeg_mem_src(&cinfo, bytes, static_cast<unsigned long>(size));
    jpeg_read_header(&cinfo, TRUE);
    *size_differs = cinfo.image_width != header.width || cinfo.image_height != header.height;
    if (!*size_differs) {
      // CMYK and YCCK (Adobe's, stored inverted) come out as CMYK; the rest as RGB.
      const bool cmyk = cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK;
      cinfo.out_color_space = cmyk ? JCS_CMYK : JCS_RGB;
      jpeg_start_decompress(&cinfo);
      for (size_t y = 0; cinfo.output_scanline < cinfo.output_height; ++y) {
        JSAMPROW rows[1] = {row};
        jpeg_read_scanlines(&cinfo, rows, 1);
        unsigned char* dst = pixels + y * width * out;
        for (size_t x = 0; x < width; ++x, dst += out) {
          const unsigned char* p = row + x * (cmyk ? 4 : 3);
          for (size_t c = 0; c < 3; ++c) dst[c] = cmyk ? static_cast<unsigned char>((p[c] * p[3] + 127) / 255) : p[c];
          if (out == 4) dst[3] = 255;
        }
      }
      jpeg_finish_decompress(&cinfo);
    }
    ok = true;
  }
  jpeg_destroy_decompress(&cinfo);
  std::memcpy(message, errors.message, sizeof message);
  return ok;
}

}  // namespace

std::optional<DecodedImage> decode_jpeg(const unsigned char* bytes, size_t size, const ImageHeader& header,
                                        int channels, std::string& error) {
  const size_t width = header.width, height = header.height, out = static_cast<size_t>(channels);
  auto* pixels = static_cast<unsigned char*>(std::malloc(width * height * out));
  auto* row = static_cast<unsigned char*>(std::malloc(width * 4));  // one scanline, up to 4 components
  if (!pixels || !row) {
    std::free(pixels);
    std::free(row);
    throw std::bad_alloc();
  }
  bool size_differs = false;
  char message[JMSG_LENGTH_MAX];
  const bool ok = decompress(bytes, size, header, out, pixels, row, &size_differs, message);
  std::free(row);
  if (!ok || size_differs) {
    std::free(pixels);
    if (!ok) error = message[0] ? message : "libjpeg gave no reason";
    else
      error = "libjpeg reads a size other than the header's " + std::to_string(width) + " x " + std::to_string(height);
    return std::nullopt;
  }
  DecodedImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.channels = channels;
  image.data = std::unique_ptr<void, void (*)(void*)>(pixels, &std::free);
  return image;
}

}  // namespace rt
