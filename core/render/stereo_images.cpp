#include "core/render/stereo_images.h"

namespace rt {
namespace {

// Eric Dubois, "A projection method to generate anaglyph stereo images", ICASSP 2001, with the
// red-cyan matrices he published for typical displays and glasses
// (www.site.uottawa.ca/~edubois/anaglyph/). Rows give the output's r, g, b from the eye's.
constexpr float kDuboisLeft[3][3] = {
    {0.456f, 0.500f, 0.176f}, {-0.040f, -0.038f, -0.016f}, {-0.015f, -0.021f, -0.005f}};
constexpr float kDuboisRight[3][3] = {
    {-0.043f, -0.088f, -0.002f}, {0.378f, 0.734f, -0.018f}, {-0.072f, -0.113f, 1.226f}};

}  // namespace

int stereo_image_width(StereoMode mode, int width) { return mode == StereoMode::kSideBySide ? 2 * width : width; }
int stereo_image_height(StereoMode mode, int height) { return mode == StereoMode::kTopBottom ? 2 * height : height; }

Vec3 anaglyph_pixel(Vec3 left, Vec3 right, AnaglyphKind kind) {
  if (kind == AnaglyphKind::kColor) return glm::clamp(Vec3(left.r, right.g, right.b), Vec3(0.0f), Vec3(1.0f));
  Vec3 out(0.0f);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col)
      out[row] += kDuboisLeft[row][col] * left[col] + kDuboisRight[row][col] * right[col];
  return glm::clamp(out, Vec3(0.0f), Vec3(1.0f));
}

Image compose_stereo(const Image& left, const Image& right, const StereoSettings& stereo) {
  const int w = left.width, h = left.height;
  Image out(stereo_image_width(stereo.mode, w), stereo_image_height(stereo.mode, h));
  const Image& first = stereo.swap ? right : left;
  const Image& second = stereo.swap ? left : right;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      switch (stereo.mode) {
        case StereoMode::kAnaglyph:
          out.at(x, y) = anaglyph_pixel(first.at(x, y), second.at(x, y), stereo.anaglyph);
          break;
        case StereoMode::kSideBySide:
          out.at(x, y) = first.at(x, y);
          out.at(x + w, y) = second.at(x, y);
          break;
        case StereoMode::kTopBottom:
          out.at(x, y) = first.at(x, y);
          out.at(x, y + h) = second.at(x, y);
          break;
        case StereoMode::kNone:
        case StereoMode::kPair: out.at(x, y) = left.at(x, y); break;
      }
    }
  }
  return out;
}

}  // namespace rt
