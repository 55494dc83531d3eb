// `rtcli merge TILE.exr... -o OUT.png|OUT.exr`: the tiles of a render split by --tile or --crop
// (EXR files) put back together (cli/frames/tile_merge.h), written as the whole render would have been:
// an EXR byte for byte, a PNG through the tiles' display transform. Exit 2 (and nothing written)
// when a tile is missing, overlaps another or comes from another render; 1 when writing fails.
// With --denoise, the merged image is denoised (the tiles must hold the denoiser's layers).
#pragma once

#include <string>
#include <vector>

namespace rt {

struct MergeCommand {
  std::vector<std::string> tiles;
  std::string output;
  bool quiet = false;
  std::string denoiser;  // --denoise / --denoiser: denoise the merged image (cli/frames/exr_denoise.h)
};

int run_merge(const MergeCommand& cmd);

}  // namespace rt
