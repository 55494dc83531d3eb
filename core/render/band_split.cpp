#include "core/render/band_split.h"

#include <algorithm>

#include "core/render/renderer.h"

namespace rt {

std::vector<int> band_edges(const std::vector<double>& row_costs, int height, int count) {
  const int preview_rows = static_cast<int>(row_costs.size());
  double total = 0.0;
  for (const double c : row_costs) total += c;
  std::vector<int> edges(static_cast<size_t>(count) + 1, 0);
  edges.back() = height;
  // The cost to the top of full-resolution row y: the preview rows above it, and a share of the
  // one it lies in.
  std::vector<double> above(static_cast<size_t>(preview_rows) + 1, 0.0);
  for (int r = 0; r < preview_rows; ++r)
    above[static_cast<size_t>(r) + 1] = above[static_cast<size_t>(r)] + row_costs[static_cast<size_t>(r)];
  const auto cost_to = [&](int y) {
    const double at = static_cast<double>(y) * preview_rows / height;
    const int r = std::min(preview_rows - 1, static_cast<int>(at));
    return above[static_cast<size_t>(r)] + (at - r) * row_costs[static_cast<size_t>(r)];
  };
  int y = 0;
  for (int k = 1; k < count; ++k) {
    const double target = total > 0.0 ? total * k / count : 0.0;
    if (total > 0.0) {
      while (y < height && cost_to(y) < target) ++y;
    } else {
      y = static_cast<int>(static_cast<int64_t>(height) * k / count);  // no cost measured: equal heights
    }
    // At least one row for this band and for each band still to come.
    y = std::clamp(y, edges[static_cast<size_t>(k) - 1] + 1, height - (count - k));
    edges[static_cast<size_t>(k)] = y;
  }
  return edges;
}

std::vector<PixelWindow> cost_balanced_bands(const Scene& scene, const RenderSettings& settings, int count,
                                             uint32_t frame) {
  RenderSettings preview = settings;
  preview.width = std::max(1, settings.width / kBandPreviewScale);
  preview.height = std::max(1, settings.height / kBandPreviewScale);
  // One camera ray per pixel: a preview with the scene's adaptive anti-aliasing balanced the toys
  // scene's bands a little better (the slowest 1.47 times the mean against 1.55) but took
  // 2.6 s of each task at 1/8 scale, against 0.15 s.
  preview.antialias.mode = "none";
  preview.path.samples_per_pixel = 1;
  preview.path.noise_threshold = 0.0f;
  std::vector<double> costs(static_cast<size_t>(preview.height), 0.0);
  if (count > 1) {
    Film film;
    for (int r = 0; r < preview.height; ++r) {
      const RenderStats s =
          render(scene, preview, film, {}, frame, RenderView{nullptr, 0, PixelWindow{0, r, preview.width, r + 1}});
      costs[static_cast<size_t>(r)] = static_cast<double>(s.rays.total());
    }
  }
  const std::vector<int> edges = band_edges(costs, settings.height, count);
  std::vector<PixelWindow> bands;
  for (int k = 0; k < count; ++k)
    bands.push_back(PixelWindow{0, edges[static_cast<size_t>(k)], settings.width, edges[static_cast<size_t>(k) + 1]});
  return bands;
}

}  // namespace rt
