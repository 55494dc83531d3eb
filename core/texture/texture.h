// An image used as a texture: linear RGB texels with a mip chain, sampled by (u, v) with a wrap
// mode and a filter. Owned by the Scene and shared read-only by every thread: sampling neither
// allocates nor locks.
//
// Conventions (docs/rendering.md, "Textures"): u runs left to right across the image and v top to bottom
// (row 0 at v = 0, as in glTF); texel (i, j) covers [i, i + 1) / width x [j, j + 1) / height and
// its centre, where bilinear filtering returns it exactly, is ((i + 0.5) / width, (j + 0.5) / height).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace rt {

enum class TextureWrap : uint8_t { kRepeat, kClamp, kMirror };
enum class TextureFilter : uint8_t { kNearest, kBilinear, kTrilinear };

// The names scene files and --texture-filter use, in enum order.
inline std::vector<std::string> texture_filter_names() { return {"nearest", "bilinear", "trilinear"}; }

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

  // The texture at (u, v). `footprint` is the width of the sampled region in (u, v) units (how
  // much of the texture one pixel's ray covers); only trilinear filtering reads it.
  Vec3 sample(Vec2 uv, TextureWrap wrap, TextureFilter filter, float footprint = 0.0f) const;
  // Bilinear filtering of one mip level: the four texels around (u, v), weighted by distance.
  Vec3 bilinear(Vec2 uv, TextureWrap wrap, int level = 0) const;
  Vec3 nearest(Vec2 uv, TextureWrap wrap, int level = 0) const;
  // The (fractional) mip level for a footprint: log2(footprint x the larger side), clamped to the chain.
  float mip_level(float footprint) const;

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<Vec3> texels;
  };
  std::vector<Level> levels_;  // level 0 the image; each next one half the size, down to 1 x 1
};

// Texel index i wrapped into [0, n) by the wrap mode.
inline int wrap_texel(int i, int n, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::kClamp: return i < 0 ? 0 : (i >= n ? n - 1 : i);
    case TextureWrap::kMirror: {
      const int period = 2 * n;
      int m = i % period;
      if (m < 0) m += period;
      return m < n ? m : period - 1 - m;
    }
    case TextureWrap::kRepeat:
    default: {
      const int m = i % n;
      return m < 0 ? m + n : m;
    }
  }
}

}  // namespace rt
