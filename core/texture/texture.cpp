#include "core/texture/texture.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/avx2_clones.h"

namespace rt {
namespace {

// Texel coordinate of u on an axis of n texels, kept in a range where float-to-int is defined:
// clamping moves u into [-1, 2]; repeat and mirror move it into [0, 2) by whole periods of both.
float texel_coordinate(float u, int n, TextureWrap wrap) {
  if (!std::isfinite(u)) u = 0.0f;
  u = wrap == TextureWrap::kClamp ? std::clamp(u, -1.0f, 2.0f) : u - 2.0f * std::floor(0.5f * u);
  return u * static_cast<float>(n);
}

}  // namespace

Texture::Texture(int width, int height, std::vector<Vec3> texels) {
  levels_.push_back(Level{width, height, std::move(texels)});
  // Each level averages 2 x 2 texels of the one above (a box filter); an odd last row or column
  // is folded into its neighbour by clamping.
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& up = levels_.back();
    Level down{std::max(1, up.width / 2), std::max(1, up.height / 2), {}};
    down.texels.resize(static_cast<size_t>(down.width) * static_cast<size_t>(down.height));
    for (int y = 0; y < down.height; ++y)
      for (int x = 0; x < down.width; ++x) {
        const auto at = [&](int i, int j) -> const Vec3& {
          i = std::min(i, up.width - 1);
          j = std::min(j, up.height - 1);
          return up.texels[static_cast<size_t>(j) * static_cast<size_t>(up.width) + static_cast<size_t>(i)];
        };
        down.texels[static_cast<size_t>(y) * static_cast<size_t>(down.width) + static_cast<size_t>(x)] =
            0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
      }
    levels_.push_back(std::move(down));
  }
}

uint64_t Texture::texels_with_mip_levels(uint64_t width, uint64_t height) {
  uint64_t total = width * height;
  while (width > 1 || height > 1) {
    width = std::max<uint64_t>(1, width / 2);
    height = std::max<uint64_t>(1, height / 2);
    total += width * height;
  }
  return total;
}

Vec3 Texture::nearest(Vec2 uv, WrapModes wrap, int level) const {
  const int w = width(level), h = height(level);
  const int x = wrap_texel(static_cast<int>(std::floor(texel_coordinate(uv.x, w, wrap.u))), w, wrap.u);
  const int y = wrap_texel(static_cast<int>(std::floor(texel_coordinate(uv.y, h, wrap.v))), h, wrap.v);
  return texel(x, y, level);
}

// Both inlined into every bilinear lookup: GCC left them out of line, a call each. The lookups are
// also cloned for AVX2 (RT_AVX2_CLONES), where SSE4.1's roundss is a floor in one instruction and
// baseline x86-64 takes about ten (a path-traced bump-mapped floor: 3% fewer instructions).
__attribute__((always_inline)) inline Texture::TexelPair Texture::texel_pair(float u, int n, TextureWrap wrap) {
  // Texel centres sit at half-integers: shift by half a texel so that they become integers.
  const float x = texel_coordinate(u, n, wrap) - 0.5f;
  const float x0 = std::floor(x);
  return {wrap_texel(static_cast<int>(x0), n, wrap), wrap_texel(static_cast<int>(x0) + 1, n, wrap), x - x0};
}

__attribute__((always_inline)) inline Vec3 Texture::blend(const TexelPair& x, const TexelPair& y, int level) const {
  const Vec3 top = (1.0f - x.f) * texel(x.i0, y.i0, level) + x.f * texel(x.i1, y.i0, level);
  const Vec3 bottom = (1.0f - x.f) * texel(x.i0, y.i1, level) + x.f * texel(x.i1, y.i1, level);
  return (1.0f - y.f) * top + y.f * bottom;
}

RT_AVX2_CLONES
Vec3 Texture::bilinear(Vec2 uv, WrapModes wrap, int level) const {
  return blend(texel_pair(uv.x, width(level), wrap.u), texel_pair(uv.y, height(level), wrap.v), level);
}

// The points (u +- du, v) share v's row pair and (u, v +- dv) u's column pair: six pairs, not
// eight. A coordinate plus 0 is itself here (texel_coordinate maps -0 and +0 alike).
RT_AVX2_CLONES
void Texture::bilinear_cross(Vec2 uv, Vec2 delta, WrapModes wrap, int level, std::array<Vec3, 4>& out) const {
  const int w = width(level), h = height(level);
  const TexelPair x = texel_pair(uv.x, w, wrap.u), y = texel_pair(uv.y, h, wrap.v);
  out[0] = blend(texel_pair(uv.x + delta.x, w, wrap.u), y, level);
  out[1] = blend(texel_pair(uv.x - delta.x, w, wrap.u), y, level);
  out[2] = blend(x, texel_pair(uv.y + delta.y, h, wrap.v), level);
  out[3] = blend(x, texel_pair(uv.y - delta.y, h, wrap.v), level);
}

float Texture::mip_level(const UvFootprint& footprint) const {
  const Vec2 size(static_cast<float>(width()), static_cast<float>(height()));
  const float texels = std::max(glm::length(footprint.axis1 * size), glm::length(footprint.axis2 * size));
  if (!(texels > 1.0f)) return 0.0f;  // also NaN
  return std::min(std::log2(texels), static_cast<float>(level_count() - 1));
}

Vec3 Texture::sample(Vec2 uv, WrapModes wrap, TextureFilter filter, const UvFootprint& footprint) const {
  return sample_at_level(uv, wrap, filter, filter_level(filter, footprint));
}

Vec3 Texture::sample_at_level(Vec2 uv, WrapModes wrap, TextureFilter filter, float level) const {
  switch (filter) {
    case TextureFilter::kNearest: return nearest(uv, wrap);
    case TextureFilter::kTrilinear: {
      const int lower = static_cast<int>(level);
      const float t = level - static_cast<float>(lower);
      if (t == 0.0f || lower + 1 >= level_count()) return bilinear(uv, wrap, lower);
      return (1.0f - t) * bilinear(uv, wrap, lower) + t * bilinear(uv, wrap, lower + 1);
    }
    case TextureFilter::kBilinear:
    default: return bilinear(uv, wrap);
  }
}

std::array<Vec3, 4> Texture::sample_cross(Vec2 uv, Vec2 delta, WrapModes wrap, TextureFilter filter,
                                          float level) const {
  std::array<Vec3, 4> out;
  if (filter == TextureFilter::kNearest) {
    const Vec2 at[4] = {uv + Vec2(delta.x, 0.0f), uv - Vec2(delta.x, 0.0f), uv + Vec2(0.0f, delta.y),
                        uv - Vec2(0.0f, delta.y)};
    for (int k = 0; k < 4; ++k) out[static_cast<size_t>(k)] = nearest(at[k], wrap);
    return out;
  }
  if (filter != TextureFilter::kTrilinear) {
    bilinear_cross(uv, delta, wrap, 0, out);
    return out;
  }
  // As sample_at_level: the level below, blended with the one above by the fraction.
  const int lower = static_cast<int>(level);
  const float t = level - static_cast<float>(lower);
  bilinear_cross(uv, delta, wrap, lower, out);
  if (t == 0.0f || lower + 1 >= level_count()) return out;
  std::array<Vec3, 4> upper;
  bilinear_cross(uv, delta, wrap, lower + 1, upper);
  for (size_t k = 0; k < 4; ++k) out[k] = (1.0f - t) * out[k] + t * upper[k];
  return out;
}

}  // namespace rt
