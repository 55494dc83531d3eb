// An image used as a texture: linear RGB texels with a mip chain, sampled by (u, v) with a wrap
// mode and a filter. Owned by the Scene and shared read-only by every thread: sampling neither
// allocates nor locks.
//
// Conventions (docs/rendering.md, "Textures"): u runs left to right across the image and v top to bottom
// (row 0 at v = 0, as in glTF); texel (i, j) covers [i, i + 1) / width x [j, j + 1) / height and
// its centre, where bilinear filtering returns it exactly, is ((i + 0.5) / width, (j + 0.5) / height).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/name_table.h"

namespace rt {

enum class TextureWrap : uint8_t { kRepeat, kClamp, kMirror };
enum class TextureFilter : uint8_t { kNearest, kBilinear, kTrilinear };

// The wrap mode of each axis (glTF's wrapS and wrapT); one mode serves both.
struct WrapModes {
  TextureWrap u = TextureWrap::kRepeat, v = TextureWrap::kRepeat;
  WrapModes() = default;
  WrapModes(TextureWrap both) : u(both), v(both) {}  // NOLINT: one mode for both axes reads naturally
  WrapModes(TextureWrap u_mode, TextureWrap v_mode) : u(u_mode), v(v_mode) {}
  bool operator==(const WrapModes& o) const { return u == o.u && v == o.v; }
};

// How much of the texture one pixel's ray covers where it meets the surface: the two axes of its
// elliptical footprint, in (u, v) units. The mip level counts texels along each axis, so that a
// 1000 x 100 image is not blurred along its long side for what its short side needs.
struct UvFootprint {
  Vec2 axis1{0.0f}, axis2{0.0f};
  UvFootprint() = default;
  UvFootprint(float width) : axis1(width, 0.0f), axis2(0.0f, width) {}  // NOLINT: a round footprint
  UvFootprint(Vec2 a1, Vec2 a2) : axis1(a1), axis2(a2) {}
  // The larger axis, in (u, v) units.
  float width() const { return std::max(glm::length(axis1), glm::length(axis2)); }
};

// The names scene files and --texture-filter use, in enum order.
inline constexpr NameEntry<TextureFilter> kTextureFilterEntries[] = {
    {"nearest", TextureFilter::kNearest, "the nearest texel"},
    {"bilinear", TextureFilter::kBilinear, "the four nearest texels blended"},
    {"trilinear", TextureFilter::kTrilinear, "bilinear in the two mip levels the ray cone's footprint falls between"}};
inline constexpr NameTable<TextureFilter> kTextureFilters{kTextureFilterEntries};

class Texture {
 public:
  // texels: width x height, row-major, row 0 at the top; both sides >= 1.
  Texture(int width, int height, std::vector<Vec3> texels);
  // The texels a width x height texture holds with its mip chain (what the constructor builds),
  // for budgets checked before an image is decoded.
  static uint64_t texels_with_mip_levels(uint64_t width, uint64_t height);

  int width(int level = 0) const { return levels_[static_cast<size_t>(level)].width; }
  int height(int level = 0) const { return levels_[static_cast<size_t>(level)].height; }
  int level_count() const { return static_cast<int>(levels_.size()); }
  const Vec3& texel(int x, int y, int level = 0) const {
    const Level& l = levels_[static_cast<size_t>(level)];
    return l.texels[static_cast<size_t>(y) * static_cast<size_t>(l.width) + static_cast<size_t>(x)];
  }

  // The texture at (u, v). `footprint`: how much of the texture one pixel's ray covers; only
  // trilinear filtering reads it.
  Vec3 sample(Vec2 uv, WrapModes wrap, TextureFilter filter, const UvFootprint& footprint = {}) const;
  // The texture at (u + du, v), (u - du, v), (u, v + dv) and (u, v - dv), in that order, at the
  // (fractional) mip level `level` (filter_level): a bump map's central differences. The same
  // floats as four lookups, with the row or column that two points share worked out once.
  std::array<Vec3, 4> sample_cross(Vec2 uv, Vec2 delta, WrapModes wrap, TextureFilter filter, float level) const;
  // The level a lookup with `filter` reads: the footprint's for trilinear filtering, else 0.
  float filter_level(TextureFilter filter, const UvFootprint& footprint) const {
    return filter == TextureFilter::kTrilinear ? mip_level(footprint) : 0.0f;
  }
  // Bilinear filtering of one mip level: the four texels around (u, v), weighted by distance.
  Vec3 bilinear(Vec2 uv, WrapModes wrap, int level = 0) const;
  Vec3 nearest(Vec2 uv, WrapModes wrap, int level = 0) const;
  // The (fractional) mip level for a footprint: log2 of the longer of its axes measured in texels
  // (u in widths, v in heights), clamped to the chain. A round footprint f gives log2(f x the
  // larger side).
  float mip_level(const UvFootprint& footprint) const;

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<Vec3> texels;
  };
  std::vector<Level> levels_;  // level 0 the image; each next one half the size, down to 1 x 1

  // One axis of a bilinear lookup: the two texels either side of the coordinate, wrapped, and
  // the weight of the second.
  struct TexelPair {
    int i0, i1;
    float f;
  };
  static TexelPair texel_pair(float u, int n, TextureWrap wrap);
  Vec3 blend(const TexelPair& x, const TexelPair& y, int level) const;  // four texels by weight
  Vec3 sample_at_level(Vec2 uv, WrapModes wrap, TextureFilter filter, float level) const;
  void bilinear_cross(Vec2 uv, Vec2 delta, WrapModes wrap, int level, std::array<Vec3, 4>& out) const;
};

// Texel index i wrapped into [0, n) by the wrap mode. The lookups' indices lie within one period
// either side of [0, 2n) (texel_coordinate reduces u to [0, 2) first), where a subtraction does
// what the remainder does: an integer division each was most of a bilinear lookup's time.
inline int wrap_texel(int i, int n, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::kClamp: return i < 0 ? 0 : (i >= n ? n - 1 : i);
    case TextureWrap::kMirror: {
      const int period = 2 * n;
      int m = i;
      if (i < 0 && i >= -period) m = i + period;
      else if (i >= period && i < 2 * period) m = i - period;
      else if (i < 0 || i >= period) m = (i % period + period) % period;  // farther out: the remainder
      return m < n ? m : period - 1 - m;
    }
    case TextureWrap::kRepeat:
    default: {
      if (i >= 0 && i < n) return i;
      if (i < 0 && i >= -n) return i + n;
      if (i >= n && i < 2 * n) return i - n;
      const int m = i % n;  // farther out: the remainder
      return m < 0 ? m + n : m;
    }
  }
}

}  // namespace rt
