// Texture sampling with real numbers: the texel-centre convention, bilinear weights, wrap modes
// at the borders, mip levels.
#include <catch2/catch.hpp>
#include <cstring>

#include "core/rng.h"
#include "core/texture/texture.h"

using namespace rt;

namespace {

// 4 x 2 texels whose red channel is 10 x column + row, so every texel is told apart.
Texture numbered() {
  std::vector<Vec3> t;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) t.emplace_back(static_cast<float>(10 * x + y), 0.0f, 1.0f);
  return Texture(4, 2, std::move(t));
}

// The centre of texel (i, j) of a 4 x 2 texture.
Vec2 centre(float i, float j) { return Vec2((i + 0.5f) / 4.0f, (j + 0.5f) / 2.0f); }

}  // namespace

TEST_CASE("bilinear filtering is exact at texel centres and averages halfway between them", "[texture]") {
  const Texture t = numbered();
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      INFO("texel " << i << ", " << j);
      CHECK(t.bilinear(centre(static_cast<float>(i), static_cast<float>(j)), TextureWrap::kClamp).x ==
            Approx(10 * i + j));
    }
  CHECK(t.bilinear(centre(1.5f, 0), TextureWrap::kClamp).x == Approx(15.0f));  // (10 + 20) / 2
  CHECK(t.bilinear(centre(1, 0.5f), TextureWrap::kClamp).x == Approx(10.5f));  // (10 + 11) / 2
  CHECK(t.bilinear(centre(1.5f, 0.5f), TextureWrap::kClamp).x == Approx(15.5f));
  // A quarter of the way: weights 3/4 and 1/4.
  CHECK(t.bilinear(centre(2.25f, 0), TextureWrap::kClamp).x == Approx(0.75f * 20 + 0.25f * 30));
  CHECK(t.nearest(centre(2.4f, 1), TextureWrap::kClamp).x == 21.0f);
  CHECK(t.nearest(Vec2(0.0f), TextureWrap::kClamp).x == 0.0f);  // texel (0, 0) covers [0, 1/4)
}

TEST_CASE("wrap modes at the borders: repeat, clamp, mirror", "[texture]") {
  const Texture t = numbered();
  // Halfway between the last column's centre and the next texel out, on row 0.
  const Vec2 past_right = centre(3.5f, 0);
  CHECK(t.bilinear(past_right, TextureWrap::kClamp).x == Approx(30.0f));         // the edge texel
  CHECK(t.bilinear(past_right, TextureWrap::kRepeat).x == Approx(15.0f));        // (30 + 0) / 2
  CHECK(t.bilinear(past_right, TextureWrap::kMirror).x == Approx(30.0f));        // 30 and its mirror 30
  CHECK(t.bilinear(centre(-0.5f, 0), TextureWrap::kRepeat).x == Approx(15.0f));  // (30 + 0) / 2
  CHECK(t.bilinear(centre(-0.5f, 0), TextureWrap::kClamp).x == Approx(0.0f));
  CHECK(t.nearest(Vec2(1.1f, 0.1f), TextureWrap::kRepeat).x == 0.0f);     // 1.1 -> 0.1: column 0
  CHECK(t.nearest(Vec2(1.1f, 0.1f), TextureWrap::kMirror).x == 30.0f);    // 1.1 -> 0.9: column 3
  CHECK(t.nearest(Vec2(-0.1f, 0.1f), TextureWrap::kMirror).x == 0.0f);    // -0.1 -> 0.1
  CHECK(t.nearest(Vec2(-0.1f, 0.1f), TextureWrap::kRepeat).x == 30.0f);   // -0.1 -> 0.9
  CHECK(t.nearest(Vec2(-7.0f, 9.0f), TextureWrap::kClamp).x == 1.0f);     // column 0, row 1
  CHECK(t.nearest(Vec2(1e30f, -1e30f), TextureWrap::kRepeat).x >= 0.0f);  // far out: still a texel
  CHECK(t.bilinear(Vec2(NAN, 0.5f), TextureWrap::kRepeat).x >= 0.0f);
  for (const int i : {-9, -5, -1, 0, 3, 4, 7, 8, 11}) {
    CHECK(wrap_texel(i, 4, TextureWrap::kRepeat) == ((i % 4) + 4) % 4);
    CHECK(wrap_texel(i, 4, TextureWrap::kClamp) == std::clamp(i, 0, 3));
  }
  CHECK(wrap_texel(4, 4, TextureWrap::kMirror) == 3);
  CHECK(wrap_texel(7, 4, TextureWrap::kMirror) == 0);
  CHECK(wrap_texel(8, 4, TextureWrap::kMirror) == 0);
  CHECK(wrap_texel(-1, 4, TextureWrap::kMirror) == 0);
  CHECK(wrap_texel(-5, 4, TextureWrap::kMirror) == 3);
  // The shortcuts near [0, 2n) and the remainder farther out give the remainder's answer everywhere.
  int differ = 0;
  for (const int n : {1, 2, 3, 7, 64, 1000})
    for (int i = -5 * n - 3; i <= 5 * n + 3; ++i) {
      const int repeat = ((i % n) + n) % n, m = ((i % (2 * n)) + 2 * n) % (2 * n);
      const int mirror = m < n ? m : 2 * n - 1 - m;
      differ += wrap_texel(i, n, TextureWrap::kRepeat) != repeat;
      differ += wrap_texel(i, n, TextureWrap::kMirror) != mirror;
    }
  CHECK(differ == 0);
}

TEST_CASE("mip levels average 2 x 2 texels down to 1 x 1, the level follows the footprint", "[texture]") {
  const Texture t = numbered();
  REQUIRE(t.level_count() == 3);  // 4 x 2, 2 x 1, 1 x 1
  CHECK(t.width(1) == 2);
  CHECK(t.height(1) == 1);
  CHECK(t.texel(0, 0, 1).x == Approx((0 + 1 + 10 + 11) / 4.0f));
  CHECK(t.texel(1, 0, 1).x == Approx((20 + 21 + 30 + 31) / 4.0f));
  CHECK(t.texel(0, 0, 2).x == Approx(15.5f));  // the mean of all eight
  CHECK(t.mip_level(0.0f) == 0.0f);
  CHECK(t.mip_level(0.25f) == 0.0f);         // one texel of the larger side
  CHECK(t.mip_level(0.5f) == Approx(1.0f));  // two texels: level 1
  CHECK(t.mip_level(0.75f) == Approx(std::log2(3.0f)));
  CHECK(t.mip_level(100.0f) == 2.0f);  // clamped to the last level
  // Trilinear: a huge footprint reads the 1 x 1 level, none the image; 1.41 texels (level 0.5)
  // blends levels 0 and 1 equally.
  CHECK(t.sample(centre(1, 0), TextureWrap::kClamp, TextureFilter::kTrilinear, 100.0f).x == Approx(15.5f));
  CHECK(t.sample(centre(1, 0), TextureWrap::kClamp, TextureFilter::kTrilinear, 0.0f).x == Approx(10.0f));
  const float half = t.sample(Vec2(0.5f, 0.5f), TextureWrap::kClamp, TextureFilter::kTrilinear, std::sqrt(2.0f) / 4).x;
  CHECK(half == Approx(0.5f * t.bilinear(Vec2(0.5f), TextureWrap::kClamp, 0).x +
                       0.5f * t.bilinear(Vec2(0.5f), TextureWrap::kClamp, 1).x));
}

TEST_CASE("wrap modes apply per axis", "[texture]") {
  const Texture t = numbered();
  // u = 1.125 + 1 texel: repeat reads column 1 (u wraps to 0.375 = column 1's centre); v = 1.75
  // clamped reads row 1, mirrored reads row 0 (1.75 mirrors to 0.25).
  const Vec2 uv(1.375f, 1.75f);
  CHECK(t.nearest(uv, WrapModes(TextureWrap::kRepeat, TextureWrap::kClamp)).x == Approx(11));
  CHECK(t.nearest(uv, WrapModes(TextureWrap::kRepeat, TextureWrap::kMirror)).x == Approx(10));
  CHECK(t.nearest(uv, WrapModes(TextureWrap::kClamp, TextureWrap::kRepeat)).x == Approx(31));
  CHECK(t.bilinear(uv, WrapModes(TextureWrap::kRepeat, TextureWrap::kClamp)).x == Approx(11));
}

TEST_CASE("the mip level counts texels along each axis of the footprint", "[texture]") {
  // A 1024 x 64 label: a footprint of one texel each way (1/1024 across u, 1/64 along v) is the
  // finest level, where measuring both by the longer side took level 4 (16 texels).
  const Texture label(1024, 64, std::vector<Vec3>(1024 * 64, Vec3(0.5f)));
  CHECK(label.mip_level(UvFootprint(Vec2(1.0f / 1024, 0.0f), Vec2(0.0f, 1.0f / 64))) == Approx(0.0f));
  CHECK(label.mip_level(UvFootprint(Vec2(4.0f / 1024, 0.0f), Vec2(0.0f, 1.0f / 64))) == Approx(2.0f));
  CHECK(label.mip_level(UvFootprint(Vec2(1.0f / 1024, 0.0f), Vec2(0.0f, 8.0f / 64))) == Approx(3.0f));
  // A round footprint is what it was: log2(footprint x the larger side).
  CHECK(label.mip_level(UvFootprint(8.0f / 1024)) == Approx(3.0f));
  const Texture square(256, 256, std::vector<Vec3>(256 * 256, Vec3(0.5f)));
  CHECK(square.mip_level(UvFootprint(Vec2(0.0f, 0.0f), Vec2(3.0f / 256, 4.0f / 256))) == Approx(std::log2(5.0f)));
}

TEST_CASE("a cross of four lookups gives the floats of four single lookups", "[texture]") {
  // sample_cross shares rows and columns between the points; each must still be what sample
  // returns on its own, bit for bit, for every filter, wrap mode and level (a bump map's normals
  // may not move). Coordinates run far outside [0, 1], to -0, and the footprints from none to
  // past the chain's end.
  std::vector<Vec3> texels;
  Rng rng(7);
  for (int i = 0; i < 13 * 6; ++i) texels.emplace_back(rng.next_float(), rng.next_float(), rng.next_float());
  const Texture t(13, 6, std::move(texels));
  const TextureWrap modes[] = {TextureWrap::kRepeat, TextureWrap::kClamp, TextureWrap::kMirror};
  const TextureFilter filters[] = {TextureFilter::kNearest, TextureFilter::kBilinear, TextureFilter::kTrilinear};
  int compared = 0;
  for (int n = 0; n < 400; ++n) {
    const Vec2 uv = n == 0 ? Vec2(-0.0f, -0.0f) : Vec2(6.0f * rng.next_float() - 3.0f, 6.0f * rng.next_float() - 3.0f);
    const Vec2 delta(0.3f * rng.next_float(), 0.3f * rng.next_float());
    const UvFootprint footprint(n % 5 == 0 ? 0.0f : 2.0f * rng.next_float() * rng.next_float());
    const Vec2 at[4] = {uv + Vec2(delta.x, 0.0f), uv - Vec2(delta.x, 0.0f), uv + Vec2(0.0f, delta.y),
                        uv - Vec2(0.0f, delta.y)};
    for (const TextureFilter filter : filters)
      for (const TextureWrap u : modes)
        for (const TextureWrap v : modes) {
          const WrapModes wrap(u, v);
          const std::array<Vec3, 4> cross = t.sample_cross(uv, delta, wrap, filter, t.filter_level(filter, footprint));
          for (size_t k = 0; k < 4; ++k) {
            const Vec3 single = t.sample(at[k], wrap, filter, footprint);
            INFO("point " << n << ", lookup " << k << ", filter " << static_cast<int>(filter));
            REQUIRE(std::memcmp(&cross[k], &single, sizeof single) == 0);
            ++compared;
          }
        }
  }
  CHECK(compared == 400 * 3 * 9 * 4);
}
