#include "tools/textures/patterns.h"

#include <cstdint>

namespace rt::textures {
namespace {

float smooth(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Lattice value noise from an integer hash (no random generator, so no platform differences).
float hash(int x, int y) {
  uint32_t h = static_cast<uint32_t>(x) * 374761393u + static_cast<uint32_t>(y) * 668265263u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return static_cast<float>((h ^ (h >> 16)) & 0xffffu) / 65535.0f;
}
float value_noise(float x, float y, int period) {
  const int xi = static_cast<int>(std::floor(x)), yi = static_cast<int>(std::floor(y));
  const float fx = smooth(0.0f, 1.0f, x - static_cast<float>(xi)), fy = smooth(0.0f, 1.0f, y - static_cast<float>(yi));
  const auto h = [&](int i, int j) { return hash(((i % period) + period) % period, ((j % period) + period) % period); };
  const float top = glm::mix(h(xi, yi), h(xi + 1, yi), fx), bottom = glm::mix(h(xi, yi + 1), h(xi + 1, yi + 1), fx);
  return glm::mix(top, bottom, fy);
}

Vec3 checker(float x, float y) {
  const bool odd = (static_cast<int>(std::floor(x * 8.0f)) + static_cast<int>(std::floor(y * 8.0f))) & 1;
  return odd ? Vec3(0.62f, 0.16f, 0.12f) : Vec3(0.93f, 0.89f, 0.78f);
}

// An 8 x 8 grid: u grows red, v grows green, so any point tells where it is; a white corner marks
// (0, 0) (top left) and a yellow bar runs along the top edge (v = 0), so flips and turns show.
Vec3 uv_grid(float x, float y) {
  const int i = static_cast<int>(x * 8.0f), j = static_cast<int>(y * 8.0f);
  Vec3 c(0.15f + 0.8f * (static_cast<float>(i) + 0.5f) / 8.0f, 0.15f + 0.8f * (static_cast<float>(j) + 0.5f) / 8.0f,
         ((i + j) & 1) ? 0.55f : 0.35f);
  const float fx = x * 8.0f - static_cast<float>(i), fy = y * 8.0f - static_cast<float>(j);
  if (fx < 0.04f || fy < 0.04f || fx > 0.96f || fy > 0.96f) c = Vec3(0.05f);
  if (y < 0.03f) c = Vec3(0.95f, 0.85f, 0.1f);
  if (x < 0.09f && y < 0.09f && x + y < 0.09f) c = Vec3(1.0f);
  return c;
}

// Planks of flat-sawn wood: rings around a pith below the board, stretched along the grain, with
// a little noise to break them up; the board runs along x. Everything repeats with period 1 in x
// and y, so the image tiles without seams: the noise has whole periods across the image, and the
// rings' arch uses (1 - cos 2 pi x) / (2 pi^2), which is x^2 near the arch's centre but periodic.
Vec3 wood(float x, float y) {
  const float plank = std::floor(y * 4.0f);
  const float py = y * 4.0f - plank;
  const float shift = hash(static_cast<int>(plank), 7) * 3.0f;
  const float wobble =
      0.35f * value_noise(x * 6.0f + shift, py * 2.0f, 6) + 0.08f * value_noise(x * 40.0f, py * 9.0f, 40);
  const float arch = (1.0f - std::cos(2.0f * kPi * (x + shift))) / (2.0f * kPi * kPi);
  const float rings = 7.0f * std::sqrt((py - 1.8f) * (py - 1.8f) + 3.0f * arch) + wobble * 2.0f;
  const float ring = rings - std::floor(rings);
  const float dark = smooth(0.55f, 0.95f, ring) * 0.8f + 0.2f * value_noise(x * 90.0f, py * 30.0f, 90);
  Vec3 c = glm::mix(Vec3(0.80f, 0.58f, 0.34f), Vec3(0.52f, 0.31f, 0.15f), dark);
  if (py < 0.012f || py > 0.988f) c *= 0.45f;  // the gap between planks
  return c;
}

bool in_heart(float x, float y) {  // (x^2 + y^2 - 1)^3 - x^2 y^3 <= 0, y up
  const float a = x * x + y * y - 1.0f;
  return a * a * a - x * x * y * y * y <= 0.0f;
}

// The ace of hearts: a white card with a rounded red border line, a large heart in the middle and
// small ones in two corners; the card is 2 : 3.
Vec3 card(float x, float y) {
  const float w = 2.0f / 3.0f;  // width / height of the 256 x 384 card
  const float cx = x * w, cy = y;
  const float r = 0.06f;
  const float dx = std::max(std::max(0.05f + r - cx, cx - (w - 0.05f - r)), 0.0f);
  const float dy = std::max(std::max(0.05f + r - cy, cy - (0.95f - r)), 0.0f);
  const float edge = std::sqrt(dx * dx + dy * dy);
  Vec3 c(0.97f, 0.96f, 0.93f);
  if (std::fabs(edge - r) < 0.006f) c = Vec3(0.75f, 0.1f, 0.12f);
  const Vec3 red(0.8f, 0.06f, 0.1f);
  if (in_heart((cx - w / 2) / 0.16f, -(cy - 0.52f) / 0.16f)) c = red;
  if (in_heart((cx - 0.13f) / 0.045f, -(cy - 0.14f) / 0.045f)) c = red;
  if (in_heart((cx - (w - 0.13f)) / 0.045f, (cy - 0.86f) / 0.045f)) c = red;  // upside down
  return c;
}

// A die's five as heights: the face at 1, five round dimples falling to 0.
Vec3 pips(float x, float y) {
  float h = 1.0f;
  const Vec2 centres[] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.5f, 0.5f}, {0.25f, 0.75f}, {0.75f, 0.75f}};
  for (const Vec2 c : centres) {
    const float d = glm::length(Vec2(x, y) - c) / 0.11f;
    if (d < 1.0f) h = std::min(h, 1.0f - std::sqrt(1.0f - d * d));
  }
  return Vec3(h);
}

// Bricks in stretcher bond: bricks at 1 with bevelled edges, mortar joints at 0.
float brick_height(float x, float y) {
  const float rows = 8.0f, cols = 4.0f;
  const float row = std::floor(y * rows);
  const float bx = x * cols + (static_cast<int>(row) % 2 ? 0.5f : 0.0f);
  const float fx = bx - std::floor(bx), fy = y * rows - row;
  const float edge = std::min(std::min(fx, 1.0f - fx) * 2.0f, std::min(fy, 1.0f - fy));  // in brick heights
  return smooth(0.04f, 0.14f, edge) * (0.92f + 0.08f * value_noise(x * 64.0f, y * 64.0f, 64));
}
Vec3 bricks(float x, float y) { return Vec3(brick_height(x, y)); }

// The same bricks as a tangent-space normal map (x right, y up the image), by central differences.
Vec3 bricks_normal(float x, float y) {
  const float e = 1.0f / 512.0f, depth = 0.04f;  // relief depth in texture widths
  const float hx = (brick_height(x + e, y) - brick_height(x - e, y)) / (2.0f * e) * depth;
  const float hy = (brick_height(x, y - e) - brick_height(x, y + e)) / (2.0f * e) * depth;  // y up
  const Vec3 n = glm::normalize(Vec3(-hx, -hy, 1.0f));
  return 0.5f * n + Vec3(0.5f);
}

// Bricks in colour, for the normal-mapped wall.
Vec3 brick_color(float x, float y) {
  const float h = brick_height(x, y);
  const float tone = value_noise(x * 4.0f, y * 8.0f, 4);
  return glm::mix(Vec3(0.72f, 0.70f, 0.66f), glm::mix(Vec3(0.62f, 0.27f, 0.18f), Vec3(0.70f, 0.36f, 0.22f), tone),
                  smooth(0.3f, 0.6f, h));
}

// A child's-room wallpaper: soft vertical stripes with a small repeating dot between them.
Vec3 wallpaper(float x, float y) {
  const float stripe = smooth(0.0f, 0.08f, std::fabs(std::fmod(x * 8.0f, 1.0f) - 0.5f) - 0.18f);
  Vec3 c = glm::mix(Vec3(0.66f, 0.75f, 0.77f), Vec3(0.88f, 0.86f, 0.79f), stripe);
  const float fx = std::fmod(x * 8.0f, 1.0f) - 0.5f, fy = std::fmod(y * 8.0f, 1.0f) - 0.5f;
  if (fx * fx + fy * fy < 0.004f) c = Vec3(0.80f, 0.62f, 0.48f);
  return c * (0.96f + 0.04f * value_noise(x * 128.0f, y * 128.0f, 128));
}

// Fine grain as heights, for a bump map (bone or plastic): two octaves of tiling value noise.
Vec3 grain(float x, float y) {
  return Vec3(0.65f * value_noise(x * 32.0f, y * 32.0f, 32) + 0.35f * value_noise(x * 96.0f, y * 96.0f, 96));
}

// A card's back: a red lattice of diamonds inside a white border.
Vec3 card_back(float x, float y) {
  const float w = 2.0f / 3.0f;
  const float cx = x * w, cy = y;
  if (cx < 0.05f || cx > w - 0.05f || cy < 0.05f || cy > 0.95f) return Vec3(0.97f, 0.96f, 0.93f);
  const float u = (cx + cy) * 14.0f, v = (cx - cy) * 14.0f;
  const float line = std::min(std::fabs(u - std::round(u)), std::fabs(v - std::round(v)));
  return line < 0.12f ? Vec3(0.97f, 0.9f, 0.88f) : Vec3(0.68f, 0.08f, 0.1f);
}

}  // namespace

const std::vector<Pattern>& patterns() {
  static const std::vector<Pattern> all = {
      {"checker.png", 256, 256, checker, "8 x 8 checkerboard"},
      {"uv_grid.png", 512, 512, uv_grid, "UV test grid: red grows with u, green with v, white corner at (0, 0)"},
      {"wood.png", 512, 512, wood, "four planks of wood grain"},
      {"card.png", 256, 384, card, "a playing card: the ace of hearts"},
      {"pips.png", 256, 256, pips, "height map: a die's five pips as dimples"},
      {"bricks.png", 256, 256, bricks, "height map: bricks with mortar joints"},
      {"bricks_normal.png", 256, 256, bricks_normal, "the same bricks as a tangent-space normal map"},
      {"bricks_colour.png", 256, 256, brick_color, "the bricks in colour"},
      {"wallpaper.png", 512, 512, wallpaper, "a child's-room wallpaper: stripes and dots"},
      {"grain.png", 256, 256, grain, "height map: fine grain (bone, plastic)"},
      {"card_back.png", 256, 384, card_back, "a playing card's back: a red diamond lattice"},
  };
  return all;
}

Rgb8Image render_pattern(const Pattern& p) {
  Rgb8Image image{p.width, p.height, ZeroedVector<uint8_t>(static_cast<size_t>(p.width) * p.height * 3)};
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
  return image;
}

const HdrPattern& sky_pattern() {
  static const HdrPattern sky{"sky.hdr", 256, 128, "test environment: blue sky, brown ground, a bright sun"};
  return sky;
}

HdrImage render_sky(const HdrPattern& p) {
  // Directions as the environment maps them (core/lights/environment.h): u from -Z round by +X,
  // v from +Y down.
  const Vec3 sun = glm::normalize(Vec3(std::sin(radians(40.0f)) * std::cos(radians(35.0f)), std::sin(radians(35.0f)),
                                       -std::cos(radians(40.0f)) * std::cos(radians(35.0f))));
  const float sun_cos = std::cos(radians(1.5f));
  HdrImage image;
  image.width = p.width;
  image.height = p.height;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      Vec3 sum(0.0f);
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const float u = (static_cast<float>(x) + (static_cast<float>(i) + 0.5f) / 4.0f) / static_cast<float>(p.width);
          const float v =
              (static_cast<float>(y) + (static_cast<float>(j) + 0.5f) / 4.0f) / static_cast<float>(p.height);
          const float longitude = (u - 0.5f) * 2.0f * kPi, theta = v * kPi;
          const Vec3 d(std::sin(theta) * std::sin(longitude), std::cos(theta), -std::sin(theta) * std::cos(longitude));
          Vec3 c;
          if (d.y >= 0.0f) {
            const float t = std::pow(d.y, 0.6f);
            c = glm::mix(Vec3(0.95f, 0.97f, 1.0f), Vec3(0.22f, 0.42f, 0.95f), t) * 1.2f;
            if (glm::dot(d, sun) > sun_cos) c = Vec3(400.0f, 380.0f, 340.0f);
          } else {
            c = Vec3(0.30f, 0.24f, 0.17f) * (0.6f + 0.4f * std::exp(8.0f * d.y));
          }
          sum += c;
        }
      image.texels.push_back(sum / 16.0f);
    }
  return image;
}

}  // namespace rt::textures
