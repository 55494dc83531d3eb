// JPEG through libjpeg-turbo (Debian's libjpeg62-turbo-dev). libjpeg reports a fatal error by
// calling error_exit, which must not return: it jumps back here with longjmp. So no object with a
// destructor is made between setjmp and the last libjpeg call, and the buffers are allocated
// before setjmp. Warnings about data libjpeg recovers from ("premature end of data segment") are
// not printed: the image decodes, with grey where the data was missing.
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <new>

#include <jpeglib.h>

#include "io/image/png_jpeg_decoder.h"

namespace rt {
namespace {

struct ErrorManager {
  jpeg_error_mgr base;  // first: libjpeg sees a jpeg_error_mgr*
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

extern "C" void jump_out(j_common_ptr cinfo) {
  auto* manager = reinterpret_cast<ErrorManager*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, manager->message);
  std::longjmp(manager->jump, 1);
}

extern "C" void stay_quiet(j_common_ptr, int) {}

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
  jpeg_decompress_struct cinfo;
  ErrorManager errors;
  cinfo.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = jump_out;
  errors.base.emit_message = stay_quiet;
  errors.message[0] = '\0';
  bool size_differs = false;
  if (setjmp(errors.jump) == 0) {
    jpeg_create_decompress(&cinfo);
    jpeg_mem_src(&cinfo, bytes, static_cast<unsigned long>(size));
    jpeg_read_header(&cinfo, TRUE);
    size_differs = cinfo.image_width != header.width || cinfo.image_height != header.height;
    if (!size_differs) {
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
    jpeg_destroy_decompress(&cinfo);
  } else {
    jpeg_destroy_decompress(&cinfo);
    std::free(pixels);
    std::free(row);
    error = errors.message[0] ? errors.message : "libjpeg gave no reason";
    return std::nullopt;
  }
  std::free(row);
  if (size_differs) {
    std::free(pixels);
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
