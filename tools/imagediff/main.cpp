// imagediff A.png B.png [DIFF.png]: how far apart two images are, in levels of 255 per channel
// (RMS, mean, max), for measurements such as anti-aliasing error against a reference
// (tools/aa_error.sh). With DIFF.png, also writes |A - B| amplified 8x.
#include <cstdio>
#include <string>

#include "io/image/png_file.h"
#include "tools/imagediff/image_compare.h"

int main(int argc, char** argv) {
  using namespace rt;
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: imagediff A.png B.png [DIFF.png]\n");
    return 2;
  }
  std::string error;
  const auto a = read_png(argv[1], error);
  const auto b = a ? read_png(argv[2], error) : std::nullopt;
  if (!a || !b) {
    std::fprintf(stderr, "imagediff: error: %s\n", error.c_str());
    return 2;
  }
  const ImageDifference d = compare_images(*a, *b, 2);
  if (!d.same_size) {
    std::fprintf(stderr, "imagediff: error: the images differ in size (%dx%d, %dx%d)\n", a->width, a->height, b->width,
                 b->height);
    return 2;
  }
  std::printf("rms %.3f mean %.3f max %d levels; %zu pixels differ by more than 2\n", d.rms_channel, d.mean_channel,
              d.max_channel, d.pixels_over);
  if (argc == 4 && !write_png(argv[3], difference_image(*a, *b), error)) {
    std::fprintf(stderr, "imagediff: error: %s\n", error.c_str());
    return 1;
  }
  return 0;
}
