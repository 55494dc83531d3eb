// thumbnail IN.png OUT.(jpg|png) [WIDTH]: IN converted to OUT, shrunk to WIDTH pixels across when
// it is wider (tools/thumbnail/shrink.h). The gallery (tools/gallery/gallery.py) uses it to
// publish large renders as JPEG with a small copy for the page.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/image/jpeg_file.h"
#include "io/image/png_file.h"
#include "tools/thumbnail/shrink.h"

int main(int argc, char** argv) {
  using namespace rt;
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: thumbnail IN.png OUT.(jpg|png) [WIDTH]\n");
    return 2;
  }
  const std::string out = argv[2];
  const int width = argc == 4 ? std::atoi(argv[3]) : 0;
  if (argc == 4 && width <= 0) {
    std::fprintf(stderr, "thumbnail: error: WIDTH must be a positive number of pixels, not '%s'\n", argv[3]);
    return 2;
  }
  std::string error;
  const auto image = read_png(argv[1], error);
  if (!image) {
    std::fprintf(stderr, "thumbnail: error: %s\n", error.c_str());
    return 2;
  }
  const Rgb8Image small = shrink_image(*image, width);
  const bool jpeg = out.size() > 4 && (out.ends_with(".jpg") || out.ends_with(".jpeg"));
  if (!(jpeg ? write_jpeg(out, small, error) : write_png(out, small, error))) {
    std::fprintf(stderr, "thumbnail: error: %s\n", error.c_str());
    return 1;
  }
  std::printf("%s  %dx%d\n", out.c_str(), small.width, small.height);
  return 0;
}
