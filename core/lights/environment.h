// The light from beyond the scene, seen by rays that meet nothing: the scene's `background`, a
// uniform colour or an equirectangular HDR image (docs/scene-format.md, "Background"). Whitted shows
// it behind the scene and in reflections; the path tracer is also lit by it, sampling an image
// by its luminance (a 2-D piecewise-constant distribution over the texels, weighted by sin(theta)
// for the area each row covers on the sphere).
//
// The image's mapping is the equirectangular camera's (core/camera.cpp): row 0 at the top (+Y),
// its centre column towards -Z, longitude growing towards +X; `rotate` turns it about +Y.
#pragma once

#include <memory>
#include <vector>

#include "core/math.h"

namespace rt {

// An equirectangular radiance image and its sampling distribution, built once and shared.
class EnvironmentImage {
 public:
  // width x height linear RGB texels, row-major, row 0 at the top; width, height >= 1.
  EnvironmentImage(int width, int height, std::vector<Vec3> texels);

  int width() const { return width_; }
  int height() const { return height_; }
  const Vec3& texel(int x, int y) const { return texels_[static_cast<size_t>(y) * width_ + x]; }
  // The texel at (u, v) in [0, 1]^2, unfiltered: constant over each texel, as the sampling
  // density is, so that radiance / density is too (a bilinear lookup spread a small sun's
  // radiance into texels the density hardly draws, and their hits became fireflies).
  Vec3 lookup(Vec2 uv) const;
  // A point of [0, 1)^2 with density pdf (over the unit square) proportional to a texel's
  // luminance x sin(theta): its row, then its column, then uniformly within the texel.
  Vec2 sample(Vec2 u, float& pdf) const;
  float pdf(Vec2 uv) const;
  bool black() const { return total_ <= 0.0; }
  // The luminance averaged over the sphere (each row weighted by the area it covers).
  float mean_luminance() const;

 private:
  int width_, height_;
  std::vector<Vec3> texels_;
  std::vector<float> row_cdf_;     // height + 1 running sums of the rows' weights, 0 to 1
  std::vector<float> column_cdf_;  // per row, width + 1 running sums, 0 to 1
  std::vector<float> weight_;      // per texel: its weight / the total (texel probability)
  double total_ = 0.0;
};

class Environment {
 public:
  Environment() = default;  // black
  explicit Environment(Vec3 color) : color_(color) {}
  Environment(std::shared_ptr<const EnvironmentImage> image, float intensity, float rotate_degrees);

  bool is_image() const { return image_ != nullptr; }
  Vec3 color() const { return color_; }  // a uniform environment's radiance
  // The radiance's luminance averaged over every direction.
  float mean_luminance() const;
  // Radiance arriving from `direction` (any length).
  Vec3 radiance(Vec3 direction) const;
  // For an image: a direction drawn by luminance, its radiance and density per unit solid angle.
  // False when there is nothing to draw (no image, or a black one).
  bool sample(Vec2 u, Vec3& direction, Vec3& radiance, float& pdf) const;
  // The density of sample() in `direction` (unit).
  float pdf(Vec3 direction) const;

  // The equirectangular coordinates of a unit direction, and back.
  Vec2 to_uv(Vec3 direction) const;
  Vec3 from_uv(Vec2 uv) const;

 private:
  Vec3 color_{0.0f};
  std::shared_ptr<const EnvironmentImage> image_;
  float intensity_ = 1.0f;
  float rotate_ = 0.0f;  // radians
};

}  // namespace rt
