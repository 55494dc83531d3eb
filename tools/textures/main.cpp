// make_textures FOLDER: writes every texture the example scenes use (tools/textures/patterns.cpp)
// into FOLDER as 8-bit RGB PNG files, and the test sky as a Radiance .hdr file.
// The output is byte-for-byte the same on every run; a test checks it against scenes/textures/.
#include <cstdio>
#include <string>

#include "io/base/atomic_file.h"
#include "io/image/hdr_file.h"
#include "io/image/png_file.h"
#include "tools/textures/patterns.h"

int main(int argc, char** argv) {
  using namespace rt;
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_textures FOLDER\n");
    return 2;
  }
  const std::string folder = argv[1];
  for (const textures::Pattern& p : textures::patterns()) {
    const Rgb8Image image = textures::render_pattern(p);
    std::string error;
    const std::string path = folder + "/" + p.file;
    if (!write_png(path, image, error)) {
      std::fprintf(stderr, "make_textures: error: %s\n", error.c_str());
      return 1;
    }
    std::printf("%s  %dx%d  %s\n", path.c_str(), p.width, p.height, p.what);
  }
  const textures::HdrPattern& sky = textures::sky_pattern();
  std::string error;
  const std::string path = folder + "/" + sky.file;
  if (!write_file_atomically(path, encode_hdr(textures::render_sky(sky)), error)) {
    std::fprintf(stderr, "make_textures: error: %s\n", error.c_str());
    return 1;
  }
  std::printf("%s  %dx%d  %s\n", path.c_str(), sky.width, sky.height, sky.what);
  return 0;
}
