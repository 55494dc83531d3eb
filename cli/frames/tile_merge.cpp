#include "cli/frames/tile_merge.h"

#include <algorithm>
#include <cstdlib>

#include "cli/frames/render_metadata.h"
#include "cli/frames/render_share.h"
#include "core/render_settings.h"

namespace rt {
namespace {

// Problems of one kind listed before the rest are only counted: thousands of tiles must not make
// millions of lines.
constexpr int kMaxListed = 10;

// What must agree between tiles, beyond the image's size and layers.
constexpr const char* kSameKeys[] = {exr_key::kVersion, exr_key::kSceneHash, exr_key::kSettingsHash, exr_key::kFrame};

std::string attribute(const ExrImage& image, const std::string& key) {
  const auto it = image.attributes.find(key);
  return it == image.attributes.end() ? "(none)" : it->second;
}

// The first "key=value;" entry of two settings texts that differs, as "key: a against b".
std::string settings_difference(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const size_t ei = a.find(';', i), ej = b.find(';', j);
    const std::string x = a.substr(i, ei - i), y = b.substr(j, ej - j);
    if (x != y) return x + " against " + y;
    if (ei == std::string::npos || ej == std::string::npos) break;
    i = ei + 1;
    j = ej + 1;
  }
  return "(the same text)";
}

std::string layout(const ExrImage& image) {
  std::string out;
  for (const ExrLayer& l : image.layers) {
    for (const std::string& c : l.channels) out += (out.empty() ? "" : ",") + (l.name.empty() ? c : l.name + "." + c);
  }
  return out;
}

std::string window_text(const PixelWindow& w) {
  return "x " + std::to_string(w.x0) + "-" + std::to_string(w.x1 - 1) + ", y " + std::to_string(w.y0) + "-" +
         std::to_string(w.y1 - 1);
}

bool overlap(const PixelWindow& a, const PixelWindow& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// The tiles' bands "I/N" when every tile is one of N: the missing ones, by number and by the rows
// between their neighbours.
void name_missing_bands(const std::vector<ExrImage>& tiles, std::vector<std::string>& problems) {
  // A band count comes from the file: more bands than rows (or than --tile takes) is no render's.
  const int most = std::min(tiles.front().height, kMaxShares);
  int count = -1;
  std::vector<bool> present;
  std::vector<PixelWindow> windows;
  for (const ExrImage& t : tiles) {
    const auto tile = t.attributes.find(exr_key::kTile);
    if (tile == t.attributes.end()) return;
    // Read as --tile reads it (0 <= I < N <= kMaxShares), never from the environment.
    std::string error;
    const auto share = parse_share(
        tile->second, exr_key::kTile, [](const std::string&) { return std::optional<std::string>(); }, error);
    if (!share) return;
    const int i = share->index, n = share->count;
    if (count >= 0 && n != count) return;
    count = n;
    if (n > most) return;
    present.resize(static_cast<size_t>(n), false);
    windows.resize(static_cast<size_t>(n));
    present[static_cast<size_t>(i)] = true;
    windows[static_cast<size_t>(i)] = t.window;
  }
  const int height = tiles.front().height;
  int missing = 0;
  for (int i = 0; i < count; ++i) {
    if (present[static_cast<size_t>(i)]) continue;
    if (++missing > kMaxListed) continue;  // counted, not listed
    // The rows from the band above's end (or the top) to the band below's start (or the bottom).
    int y0 = i == 0 ? 0 : -1, y1 = i == count - 1 ? height : -1;
    if (i > 0 && present[static_cast<size_t>(i) - 1]) y0 = windows[static_cast<size_t>(i) - 1].y1;
    if (i + 1 < count && present[static_cast<size_t>(i) + 1]) y1 = windows[static_cast<size_t>(i) + 1].y0;
    const std::string rows =
        y0 >= 0 && y1 > y0 ? " (rows " + std::to_string(y0) + "-" + std::to_string(y1 - 1) + ")" : "";
    problems.push_back("tile " + std::to_string(i) + "/" + std::to_string(count) + rows +
                       " is missing: render it with --tile " + std::to_string(i) + "/" + std::to_string(count));
  }
  if (missing > kMaxListed)
    problems.push_back("... and " + std::to_string(missing - kMaxListed) + " more tiles of " + std::to_string(count) +
                       " are missing (" + std::to_string(missing) + " in all)");
}

}  // namespace

std::optional<ExrImage> merge_tiles(const std::vector<std::string>& paths, std::vector<std::string>& problems,
                                    uint64_t max_pixels) {
  std::vector<ExrImage> tiles;
  uint64_t held = 0;  // pixels of the tiles read
  for (const std::string& path : paths) {
    std::string error;
    auto tile = read_exr(path, max_pixels, error);
    if (!tile) {
      problems.push_back(error);
      continue;
    }
    const ExrLayer* color = tile->layer("");
    if (!color || color->channels.size() < 3 || color->channels[0] != "R" || color->channels[1] != "G" ||
        color->channels[2] != "B") {
      problems.push_back(path + ": expected the colour channels R, G, B");
      continue;
    }
    held += tile->window.pixels();
    tiles.push_back(std::move(*tile));
    // Tiles that each hold their own pixels hold the image's at most: past that some overlap, and
    // reading on (thousands of whole-image tiles) would only fill memory.
    if (held > static_cast<uint64_t>(tiles.front().width) * static_cast<uint64_t>(tiles.front().height)) break;
  }
  if (!problems.empty() || tiles.empty()) return std::nullopt;

  // The same render.
  const ExrImage& first = tiles.front();
  for (size_t k = 1; k < tiles.size(); ++k) {
    const ExrImage& t = tiles[k];
    const std::string against = paths[k] + " against " + paths[0] + ": ";
    if (t.width != first.width || t.height != first.height)
      problems.push_back(against + "an image of " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                         " against " + std::to_string(first.width) + "x" + std::to_string(first.height));
    if (layout(t) != layout(first)) problems.push_back(against + "channels " + layout(t) + " against " + layout(first));
    if (t.full_float != first.full_float)
      problems.push_back(against + (t.full_float ? "float" : "half") + " channels against " +
                         (first.full_float ? "float" : "half"));
    for (const char* key : kSameKeys) {
      if (attribute(t, key) == attribute(first, key)) continue;
      std::string why = against + "a different " + std::string(key).substr(6) + " (" + attribute(t, key) + " against " +
                        attribute(first, key) + ")";
      if (std::string(key) == exr_key::kSettingsHash)
        why += ": " + settings_difference(attribute(t, exr_key::kSettings), attribute(first, exr_key::kSettings));
      if (std::string(key) == exr_key::kSceneHash) why += ": the scene or a file it reads changed between the renders";
      problems.push_back(why);
    }
  }
  if (!problems.empty()) return std::nullopt;

  // Exactly once: the first few overlapping pairs named, the rest counted.
  uint64_t overlapping = 0;
  for (size_t a = 0; a < tiles.size(); ++a)
    for (size_t b = a + 1; b < tiles.size(); ++b)
      if (overlap(tiles[a].window, tiles[b].window) && ++overlapping <= kMaxListed)
        problems.push_back(paths[a] + " (" + window_text(tiles[a].window) + ") and " + paths[b] + " (" +
                           window_text(tiles[b].window) + ") overlap");
  if (overlapping > kMaxListed)
    problems.push_back("... and " + std::to_string(overlapping - kMaxListed) + " more overlapping pairs among the " +
                       std::to_string(tiles.size()) + " tiles read");
  if (overlapping > 0 && tiles.size() < paths.size())
    problems.push_back("the first " + std::to_string(tiles.size()) + " of the " + std::to_string(paths.size()) +
                       " tiles already hold more pixels than the image: reading stopped there");
  if (!problems.empty()) return std::nullopt;
  uint64_t covered = 0;
  for (const ExrImage& t : tiles) covered += t.window.pixels();
  const uint64_t all = static_cast<uint64_t>(first.width) * static_cast<uint64_t>(first.height);
  if (covered != all) {
    name_missing_bands(tiles, problems);
    if (problems.empty()) {
      // The first row with a pixel no tile holds, and its run.
      for (int y = 0; y < first.height && problems.empty(); ++y) {
        std::vector<std::pair<int, int>> spans;
        for (const ExrImage& t : tiles)
          if (y >= t.window.y0 && y < t.window.y1) spans.emplace_back(t.window.x0, t.window.x1);
        std::sort(spans.begin(), spans.end());
        int x = 0;
        for (const auto& [x0, x1] : spans) {
          if (x0 > x) break;
          x = std::max(x, x1);
        }
        if (x < first.width)
          problems.push_back("no tile holds pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                             "); the tiles cover " + std::to_string(covered) + " of the image's " +
                             std::to_string(all) + " pixels");
      }
    }
    return std::nullopt;
  }

  // Put together.
  ExrImage out;
  out.width = first.width;
  out.height = first.height;
  out.window = PixelWindow::whole(first.width, first.height);
  out.full_float = first.full_float;
  out.attributes = first.attributes;
  out.attributes[exr_key::kCrop] = "0,0," + std::to_string(first.width) + "," + std::to_string(first.height);
  out.attributes.erase(exr_key::kTile);
  for (const ExrLayer& l : first.layers)
    out.layers.push_back(ExrLayer{l.name, l.channels, std::vector<float>(all * l.channels.size()), l.exact});
  for (const ExrImage& t : tiles) {
    const PixelWindow& w = t.window;
    for (size_t k = 0; k < out.layers.size(); ++k) {
      const size_t n = out.layers[k].channels.size();
      for (int y = w.y0; y < w.y1; ++y) {
        const float* from =
            t.layers[k].values.data() + static_cast<size_t>(y - w.y0) * static_cast<size_t>(w.width()) * n;
        float* to = out.layers[k].values.data() +
                    (static_cast<size_t>(y) * static_cast<size_t>(out.width) + static_cast<size_t>(w.x0)) * n;
        std::copy(from, from + static_cast<size_t>(w.width()) * n, to);
      }
    }
  }
  return out;
}

}  // namespace rt
