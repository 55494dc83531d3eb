// Which part of a render this process does, for renders split across processes or machines:
//   --crop x0,y0,x1,y1  pixels [x0, x1) x [y0, y1) of the image;
//   --tile I/N          band I (0-based) of N horizontal bands of whole rows of about equal cost
//                       (core/render/band_split.h; docs/cluster.md says how to choose N);
//   --chunk I/N         share I of N of the frames, consecutive, sizes differing by at most one;
//   auto for I/N        the share of this Slurm array task: I = SLURM_ARRAY_TASK_ID -
//                       SLURM_ARRAY_TASK_MIN, N = SLURM_ARRAY_TASK_COUNT.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/pixel_window.h"

namespace rt {

// The most parts --tile and --chunk split a render into.
inline constexpr int kMaxShares = 100000;

struct Share {
  int index = 0, count = 1;
};

// The environment's variable `name`, or nothing (tests pass their own).
using EnvironmentLookup = std::function<std::optional<std::string>(const std::string& name)>;
EnvironmentLookup process_environment();

// "I/N" or "auto" (for `option`, named in errors); nothing, with `error`, when it is neither or
// auto finds no Slurm array.
std::optional<Share> parse_share(const std::string& text, const char* option, const EnvironmentLookup& env,
                                 std::string& error);

// "I/N": how a share is written, in rtcli:tile and messages; parse_share reads it back.
std::string share_text(const Share& share);

// "x0,y0,x1,y1": four whole numbers, 0 <= x0 < x1 and 0 <= y0 < y1; nothing, with `error`,
// otherwise. Whether it fits the image is crop_fits' to say, once the image's size is known.
std::optional<PixelWindow> parse_crop_text(const std::string& text, std::string& error);
// Whether the window lies inside a width x height image; `error` says why not.
bool crop_fits(const PixelWindow& crop, int width, int height, std::string& error);

}  // namespace rt
