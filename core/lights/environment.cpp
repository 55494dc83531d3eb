#include "core/lights/environment.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

float luminance(Vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// The index i with cdf[i] <= x < cdf[i + 1], among cdf.size() - 1 intervals of positive width.
size_t find_interval(const float* cdf, size_t intervals, float x) {
  const float* it = std::upper_bound(cdf, cdf + intervals + 1, x);
  size_t i = static_cast<size_t>(std::max<std::ptrdiff_t>(0, it - cdf - 1));
  i = std::min(i, intervals - 1);
  // Skip empty intervals (a zero weight), which upper_bound may land on at their shared edge.
  while (i + 1 < intervals && cdf[i + 1] <= cdf[i]) ++i;
  return i;
}

}  // namespace

EnvironmentImage::EnvironmentImage(int width, int height, std::vector<Vec3> texels)
    : width_(width), height_(height), texels_(std::move(texels)) {
  const size_t w = static_cast<size_t>(width_), h = static_cast<size_t>(height_);
  weight_.assign(w * h, 0.0f);
  column_cdf_.assign(h * (w + 1), 0.0f);
  row_cdf_.assign(h + 1, 0.0f);
  std::vector<double> row_sum(h, 0.0);
  for (size_t y = 0; y < h; ++y) {
    const double sin_theta = std::sin(kPi * (static_cast<double>(y) + 0.5) / static_cast<double>(h));
    double sum = 0.0;
    for (size_t x = 0; x < w; ++x) {
      const float l = luminance(texels_[y * w + x]);
      const double weight = std::isfinite(l) && l > 0.0f ? l * sin_theta : 0.0;
      weight_[y * w + x] = static_cast<float>(weight);
      sum += weight;
      column_cdf_[y * (w + 1) + x + 1] = static_cast<float>(sum);
    }
    row_sum[y] = sum;
    total_ += sum;
  }
  if (total_ <= 0.0) return;
  double running = 0.0;
  for (size_t y = 0; y < h; ++y) {
    running += row_sum[y];
    row_cdf_[y + 1] = static_cast<float>(running / total_);
    for (size_t x = 1; x <= w; ++x) {
      float& c = column_cdf_[y * (w + 1) + x];
      c = row_sum[y] > 0.0 ? static_cast<float>(c / row_sum[y]) : static_cast<float>(x) / static_cast<float>(w);
    }
    for (size_t x = 0; x < w; ++x) weight_[y * w + x] = static_cast<float>(weight_[y * w + x] / total_);
  }
  row_cdf_[h] = 1.0f;
  for (size_t y = 0; y < h; ++y) column_cdf_[y * (w + 1) + w] = 1.0f;
}

Vec3 EnvironmentImage::lookup(Vec2 uv) const {
  const int x = std::clamp(static_cast<int>(uv.x * static_cast<float>(width_)), 0, width_ - 1);
  const int y = std::clamp(static_cast<int>(uv.y * static_cast<float>(height_)), 0, height_ - 1);
  return texel(x, y);
}

Vec2 EnvironmentImage::sample(Vec2 u, float& pdf) const {
  const size_t w = static_cast<size_t>(width_), h = static_cast<size_t>(height_);
  const size_t y = find_interval(row_cdf_.data(), h, u.y);
  const float row_width = row_cdf_[y + 1] - row_cdf_[y];
  const float v_in = row_width > 0.0f ? std::clamp((u.y - row_cdf_[y]) / row_width, 0.0f, 0.99999994f) : 0.5f;
  const float* cdf = column_cdf_.data() + y * (w + 1);
  const size_t x = find_interval(cdf, w, u.x);
  const float column_width = cdf[x + 1] - cdf[x];
  const float u_in = column_width > 0.0f ? std::clamp((u.x - cdf[x]) / column_width, 0.0f, 0.99999994f) : 0.5f;
  pdf = weight_[y * w + x] * static_cast<float>(w * h);
  return Vec2((static_cast<float>(x) + u_in) / static_cast<float>(w),
              (static_cast<float>(y) + v_in) / static_cast<float>(h));
}

float EnvironmentImage::pdf(Vec2 uv) const {
  const int x = std::clamp(static_cast<int>(uv.x * static_cast<float>(width_)), 0, width_ - 1);
  const int y = std::clamp(static_cast<int>(uv.y * static_cast<float>(height_)), 0, height_ - 1);
  return weight_[static_cast<size_t>(y) * width_ + x] * static_cast<float>(width_ * height_);
}

Environment::Environment(std::shared_ptr<const EnvironmentImage> image, float intensity, float rotate_degrees)
    : image_(std::move(image)), intensity_(intensity), rotate_(radians(rotate_degrees)) {}

Vec2 Environment::to_uv(Vec3 d) const {
  d = glm::normalize(d);
  float longitude = std::atan2(d.x, -d.z) - rotate_;                      // 0 towards -Z, pi/2 towards +X
  longitude -= 2.0f * kPi * std::floor(longitude / (2.0f * kPi) + 0.5f);  // into [-pi, pi)
  const float u = 0.5f + longitude / (2.0f * kPi);
  const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
  return Vec2(std::clamp(u, 0.0f, 1.0f), v);
}

Vec3 Environment::from_uv(Vec2 uv) const {
  const float longitude = (uv.x - 0.5f) * 2.0f * kPi + rotate_;
  const float theta = uv.y * kPi;
  const float s = std::sin(theta);
  return Vec3(s * std::sin(longitude), std::cos(theta), -s * std::cos(longitude));
}

Vec3 Environment::radiance(Vec3 direction) const {
  if (!image_) return color_;
  return intensity_ * image_->lookup(to_uv(direction));
}

bool Environment::sample(Vec2 u, Vec3& direction, Vec3& radiance_out, float& pdf_out) const {
  if (!image_ || image_->black()) return false;
  float pdf_uv = 0.0f;
  const Vec2 uv = image_->sample(u, pdf_uv);
  const float sin_theta = std::sin(uv.y * kPi);
  if (!(pdf_uv > 0.0f) || !(sin_theta > 0.0f)) return false;
  direction = from_uv(uv);
  radiance_out = intensity_ * image_->lookup(uv);
  // du dv = dw / (2 pi^2 sin theta)
  pdf_out = pdf_uv / (2.0f * kPi * kPi * sin_theta);
  return true;
}

float Environment::pdf(Vec3 direction) const {
  if (!image_ || image_->black()) return 0.0f;
  const Vec2 uv = to_uv(direction);
  const float sin_theta = std::sin(uv.y * kPi);
  if (!(sin_theta > 0.0f)) return 0.0f;
  return image_->pdf(uv) / (2.0f * kPi * kPi * sin_theta);
}

float EnvironmentImage::mean_luminance() const {
  // The rows' sin(theta) weights sum to about height x 2 / pi per column.
  if (width_ <= 0 || height_ <= 0) return 0.0f;
  return static_cast<float>(total_ * kPi / (2.0 * width_ * height_));
}

float Environment::mean_luminance() const {
  if (image_) return intensity_ * image_->mean_luminance();
  return (color_.x + color_.y + color_.z) / 3.0f;
}

}  // namespace rt
