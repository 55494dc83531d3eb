// make_textures FOLDER: writes every texture the example scenes use (tools/textures/patterns.cpp)
// into FOLDER as 8-bit RGB PNG files, each texel the average of 4 x 4 points so edges are smooth.
// The output is byte-for-byte the same on every run; a test checks it against scenes/textures/.
#include <cstdio>
#include <string>

#include "io/png_file.h"
#include "tools/textures/patterns.h"

int main(int argc, char** argv) {
  using namespace rt;
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_textures FOLDER\n");
    return 2;
  }
  const std::string folder = argv[1];
  for (const textures::Pattern& p : textures::patterns()) {
    Rgb8Image image{p.width, p.height, std::vector<uint8_t>(static_cast<size_t>(p.width) * p.height * 3)};
    constexpr int kSub = 4;
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < p.width; ++x) {
        Vec3 sum(0.0f);
        for (int j = 0; j < kSub; ++j)
          for (int i = 0; i < kSub; ++i)
            sum += p.at((static_cast<float>(x) + (static_cast<float>(i) + 0.5f) / kSub) / static_cast<float>(p.width),
                        (static_cast<float>(y) + (static_cast<float>(j) + 0.5f) / kSub) / static_cast<float>(p.height));
        const Vec3 v = glm::clamp(sum / static_cast<float>(kSub * kSub), Vec3(0.0f), Vec3(1.0f));
        for (int c = 0; c < 3; ++c)
          image.rgb[(static_cast<size_t>(y) * static_cast<size_t>(p.width) + static_cast<size_t>(x)) * 3 +
                    static_cast<size_t>(c)] = static_cast<uint8_t>(std::lround(v[c] * 255.0f));
      }
    std::string error;
    const std::string path = folder + "/" + p.file;
    if (!write_png(path, image, error)) {
      std::fprintf(stderr, "make_textures: error: %s\n", error.c_str());
      return 1;
    }
    std::printf("%s  %dx%d  %s\n", path.c_str(), p.width, p.height, p.what);
  }
  return 0;
}
