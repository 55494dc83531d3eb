// The image (or the window of it being rendered) cut into square tiles: the unit of work a thread
// takes, and of a sampler's film. Tiles are in the image's coordinates.
#pragma once

#include <algorithm>
#include <vector>

#include "core/pixel_window.h"

namespace rt {

struct Tile {
  int index = 0;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) x [y0, y1)
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

struct TileGrid {
  PixelWindow window;  // what is cut
  int size = 1;        // tile side in pixels
  int columns = 0, rows = 0;

  TileGrid(int image_width, int image_height, int tile_size)
      : TileGrid(PixelWindow::whole(image_width, image_height), tile_size) {}
  TileGrid(PixelWindow cut, int tile_size) : window(cut), size(std::max(1, tile_size)) {
    columns = window.empty() ? 0 : (window.width() + size - 1) / size;
    rows = window.empty() ? 0 : (window.height() + size - 1) / size;
  }
  int count() const { return columns * rows; }
  Tile tile(int index) const {
    const int x0 = window.x0 + (index % columns) * size, y0 = window.y0 + (index / columns) * size;
    return Tile{index, x0, y0, std::min(x0 + size, window.x1), std::min(y0 + size, window.y1)};
  }
  // The tile left of / above tile `index`, or -1 at the image border.
  int left(int index) const { return index % columns == 0 ? -1 : index - 1; }
  int above(int index) const { return index < columns ? -1 : index - columns; }
  int right(int index) const { return index % columns == columns - 1 ? -1 : index + 1; }
  int below(int index) const { return index + columns >= count() ? -1 : index + columns; }

  // Every tile in row-major order, or in anti-diagonal order (a wavefront from the top-left
  // corner), where each tile comes after the tiles left of it and above it.
  std::vector<int> order(bool wavefront) const {
    std::vector<int> out;
    out.reserve(static_cast<size_t>(count()));
    if (!wavefront) {
      for (int i = 0; i < count(); ++i) out.push_back(i);
      return out;
    }
    for (int diagonal = 0; diagonal < columns + rows - 1; ++diagonal)
      for (int row = std::max(0, diagonal - columns + 1); row <= std::min(diagonal, rows - 1); ++row)
        out.push_back(row * columns + (diagonal - row));
    return out;
  }
};

}  // namespace rt
