// The display transform (core/tone_map.h): exposure in stops, the clamp and filmic curves, and
// the 8-bit encoding through it.
#include <catch2/catch.hpp>

#include "core/color.h"
#include "core/tone_map.h"
#include "io/image/rgb8_image.h"

using namespace rt;

namespace {

// Narkowicz's ACES fit in double, for reference.
double aces(double x) { return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14); }

}  // namespace

TEST_CASE("tone map: the filmic curve is Narkowicz's ACES fit, clamped to [0, 1]", "[color][tonemap]") {
  CHECK(DisplayTransform::filmic(0.0f) == 0.0f);
  CHECK(DisplayTransform::filmic(-1.0f) == 0.0f);
  CHECK(DisplayTransform::filmic(std::nanf("")) == 0.0f);
  CHECK(DisplayTransform::filmic(kInfinity) == 1.0f);
  CHECK(DisplayTransform::filmic(0.18f) == Approx(0.26690).epsilon(1e-4));  // mid grey, lifted a little
  CHECK(DisplayTransform::filmic(1.0f) == Approx(2.54 / 3.16).epsilon(1e-6));
  CHECK(DisplayTransform::filmic(4.0f) == Approx(40.28 / 41.38).epsilon(1e-6));
  CHECK(DisplayTransform::filmic(100.0f) == 1.0f);  // past x = 7.24 the fit exceeds 1
  // Increasing, never above 1, and the float formula within rounding of the double one.
  float last = 0.0f;
  for (int i = 1; i <= 2000; ++i) {
    const float x = static_cast<float>(i) * 0.005f;
    const float y = DisplayTransform::filmic(x);
    CHECK(y >= last);
    CHECK(y <= 1.0f);
    CHECK(y == Approx(std::min(1.0, aces(x))).epsilon(1e-5));
    last = y;
  }
}

TEST_CASE("tone map: exposure multiplies by 2^stops before the curve, the default changes nothing",
          "[color][tonemap]") {
  DisplayTransform t;
  CHECK(t.identity());
  CHECK(t.apply(0.3f) == 0.3f);
  CHECK(t.apply(5.0f) == 5.0f);  // the clamp at 1 is the sRGB encoding's
  t.exposure = 1.0f;
  CHECK_FALSE(t.identity());
  CHECK(t.apply(0.25f) == 0.5f);
  t.exposure = -2.0f;
  CHECK(t.apply(0.8f) == 0.2f);
  t.curve = ToneMap::kFilmic;
  CHECK(t.apply(4.0f) == DisplayTransform::filmic(1.0f));
  const Vec3 v = t.apply(Vec3(4.0f, 0.0f, 8.0f));
  CHECK(v.x == DisplayTransform::filmic(1.0f));
  CHECK(v.y == 0.0f);
  CHECK(v.z == DisplayTransform::filmic(2.0f));
}

TEST_CASE("tone map: 8-bit encoding through the transform", "[color][tonemap]") {
  Image image(4, 1);
  image.pixels = {Vec3(0.0f), Vec3(0.18f), Vec3(1.0f), Vec3(2.0f, 8.0f, 100.0f)};
  // The default: exactly the clamp-and-encode rule of before.
  const Rgb8Image plain = encode_srgb8(image);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) CHECK(plain.rgb[3 * i + static_cast<size_t>(c)] == srgb8(image.pixels[i][c]));
  CHECK(plain.rgb[9] == 255);  // 2, 8 and 100 all flat white
  CHECK(plain.rgb[10] == 255);
  // Filmic: the highlights keep their order below white until past 7.24.
  DisplayTransform filmic;
  filmic.curve = ToneMap::kFilmic;
  const Rgb8Image rolled = encode_srgb8(image, filmic);
  CHECK(rolled.rgb[0] == 0);
  CHECK(rolled.rgb[6] < 255);            // 1.0 is no longer white
  CHECK(rolled.rgb[9] > rolled.rgb[6]);  // 2 above 1
  CHECK(rolled.rgb[9] < 255);
  CHECK(rolled.rgb[10] == 255);  // 8: past the shoulder
  CHECK(rolled.rgb[9] == srgb8(DisplayTransform::filmic(2.0f)));
}
