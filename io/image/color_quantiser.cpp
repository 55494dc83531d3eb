#include "io/image/color_quantiser.h"

#include <algorithm>
#include <unordered_map>

namespace rt {
namespace {

struct Color {
  std::array<uint8_t, 3> rgb;
  uint32_t count;  // pixels of this colour
};

uint32_t key(const uint8_t* p) { return (uint32_t{p[0]} << 16) | (uint32_t{p[1]} << 8) | p[2]; }

// The distinct colours of the image with their pixel counts, in a fixed order.
std::vector<Color> histogram(const Rgb8Image& image) {
  std::vector<uint32_t> keys(image.rgb.size() / 3);
  for (size_t i = 0; i < keys.size(); ++i) keys[i] = key(&image.rgb[3 * i]);
  std::sort(keys.begin(), keys.end());
  std::vector<Color> out;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    const uint32_t k = keys[i];
    out.push_back(Color{{static_cast<uint8_t>(k >> 16), static_cast<uint8_t>(k >> 8), static_cast<uint8_t>(k)},
                        static_cast<uint32_t>(j - i)});
    i = j;
  }
  return out;
}

struct Box {
  size_t begin, end;  // in the colour array
  uint64_t pixels = 0;
  int axis = 0;   // the channel with the widest range
  int range = 0;  // of that channel

  void measure(const std::vector<Color>& colors) {
    int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
    pixels = 0;
    for (size_t i = begin; i < end; ++i) {
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min<int>(lo[c], colors[i].rgb[c]);
        hi[c] = std::max<int>(hi[c], colors[i].rgb[c]);
      }
      pixels += colors[i].count;
    }
    axis = 0;
    for (int c = 1; c < 3; ++c)
      if (hi[c] - lo[c] > hi[axis] - lo[axis]) axis = c;
    range = hi[axis] - lo[axis];
  }
  // Which box to split next: many pixels spread over a wide range of one channel.
  uint64_t priority() const { return end - begin > 1 ? pixels * static_cast<uint64_t>(range) : 0; }
};

}  // namespace

std::vector<std::array<uint8_t, 3>> median_cut_palette(const Rgb8Image& image, int max_colors) {
  std::vector<Color> colors = histogram(image);
  std::vector<Box> boxes;
  if (colors.empty()) return {{0, 0, 0}};
  boxes.push_back(Box{0, colors.size()});
  boxes.back().measure(colors);
  while (static_cast<int>(boxes.size()) < max_colors) {
    const auto widest = std::max_element(boxes.begin(), boxes.end(),
                                         [](const Box& a, const Box& b) { return a.priority() < b.priority(); });
    if (widest->priority() == 0) break;  // every box is one colour (or zero-range): nothing to split
    Box& box = *widest;
    const int axis = box.axis;
    std::sort(colors.begin() + static_cast<ptrdiff_t>(box.begin), colors.begin() + static_cast<ptrdiff_t>(box.end),
              [axis](const Color& a, const Color& b) {
                return a.rgb[axis] != b.rgb[axis] ? a.rgb[axis] < b.rgb[axis] : key(a.rgb.data()) < key(b.rgb.data());
              });
    // Split at the pixel-weighted median, keeping at least one colour on each side.
    uint64_t seen = 0;
    size_t split = box.begin + 1;
    for (size_t i = box.begin; i + 1 < box.end; ++i) {
      seen += colors[i].count;
      split = i + 1;
      if (2 * seen >= box.pixels) break;
    }
    Box upper{split, box.end};
    box.end = split;
    box.measure(colors);
    upper.measure(colors);
    boxes.push_back(upper);
  }
  std::vector<std::array<uint8_t, 3>> palette;
  for (const Box& b : boxes) {
    uint64_t sum[3] = {0, 0, 0};
    for (size_t i = b.begin; i < b.end; ++i)
      for (int c = 0; c < 3; ++c) sum[c] += uint64_t{colors[i].rgb[c]} * colors[i].count;
    std::array<uint8_t, 3> mean{};
    for (int c = 0; c < 3; ++c) mean[c] = static_cast<uint8_t>((sum[c] + b.pixels / 2) / b.pixels);
    palette.push_back(mean);
  }
  return palette;
}

IndexedImage quantise(const Rgb8Image& image, bool dither, int max_colors) {
  IndexedImage out;
  out.width = image.width;
  out.height = image.height;
  out.palette = median_cut_palette(image, std::clamp(max_colors, 1, 256));
  out.indices.resize(static_cast<size_t>(image.width) * static_cast<size_t>(image.height));
  std::unordered_map<uint32_t, uint8_t> nearest_of;  // colour -> palette index, found once per colour
  nearest_of.reserve(4096);
  const auto nearest = [&](int r, int g, int b) {
    const uint32_t k = (static_cast<uint32_t>(r) << 16) | (static_cast<uint32_t>(g) << 8) | static_cast<uint32_t>(b);
    if (const auto it = nearest_of.find(k); it != nearest_of.end()) return it->second;
    int best = 0, best_d = 1 << 30;
    for (size_t i = 0; i < out.palette.size(); ++i) {
      const int dr = r - out.palette[i][0], dg = g - out.palette[i][1], db = b - out.palette[i][2];
      const int d = dr * dr + dg * dg + db * db;
      if (d < best_d) {
        best_d = d;
        best = static_cast<int>(i);
      }
    }
    return nearest_of[k] = static_cast<uint8_t>(best);
  };
  const int w = image.width;
  // Floyd-Steinberg: the error of each pixel goes to its unvisited neighbours (7, 3, 5, 1 / 16),
  // carried in two rows of integers (sixteenths of a level).
  std::vector<int> error_row(3 * static_cast<size_t>(w + 2), 0), next_row(error_row.size(), 0);
  for (int y = 0; y < image.height; ++y) {
    std::fill(next_row.begin(), next_row.end(), 0);
    for (int x = 0; x < w; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
      int c[3];
      for (int k = 0; k < 3; ++k) {
        const int diffused = dither ? error_row[3 * static_cast<size_t>(x + 1) + static_cast<size_t>(k)] : 0;
        c[k] = std::clamp(
            image.rgb[3 * p + static_cast<size_t>(k)] + (diffused >= 0 ? diffused + 8 : diffused - 8) / 16, 0, 255);
      }
      const uint8_t index = nearest(c[0], c[1], c[2]);
      out.indices[p] = index;
      if (!dither) continue;
      for (int k = 0; k < 3; ++k) {
        const int e = c[k] - out.palette[index][static_cast<size_t>(k)];
        const auto at = [&](std::vector<int>& row, int dx) -> int& {
          return row[3 * static_cast<size_t>(x + 1 + dx) + static_cast<size_t>(k)];
        };
        at(error_row, 1) += 7 * e;
        at(next_row, -1) += 3 * e;
        at(next_row, 0) += 5 * e;
        at(next_row, 1) += 1 * e;
      }
    }
    std::swap(error_row, next_row);
  }
  return out;
}

}  // namespace rt
