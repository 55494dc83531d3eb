// The image cut into N bands of whole rows that cost about the same to render (rtcli render
// --tile I/N): rows differ widely in cost (a glass ball's rows trace ten times the rays of the
// sky's), so equal heights leave some tasks of a split render waiting on others. The cost of each
// row is measured by a preview: the same scene and settings at 1/kBandPreviewScale of the width
// and height, one camera ray per pixel (the path tracer one sample), its rays counted row by row.
// The bands follow the preview's cumulative cost. Deterministic: the counts depend only on the
// scene and settings, so every task of a split render computes the same bands.
#pragma once

#include <vector>

#include "core/pixel_window.h"
#include "core/render_settings.h"
#include "core/scene.h"

namespace rt {

inline constexpr int kBandPreviewScale = 16;

// The `count` bands' windows, top to bottom; each has at least one row (count <= settings.height).
std::vector<PixelWindow> cost_balanced_bands(const Scene& scene, const RenderSettings& settings, int count,
                                             uint32_t frame = 0);

// Where the cumulative cost of `row_costs` (rows of a preview) crosses each k/count of the total,
// scaled to `height` rows: the `count` bands' first rows, then `height`. Bands never empty.
std::vector<int> band_edges(const std::vector<double>& row_costs, int height, int count);

}  // namespace rt
