#include "cli/frames/merge_command.h"

#include <cstdio>

#include "cli/common/exit_codes.h"
#include "cli/frames/exr_denoise.h"
#include "cli/frames/exr_display.h"
#include "cli/frames/frame_output.h"
#include "cli/frames/output_checks.h"
#include "cli/frames/tile_merge.h"
#include "core/thread_count.h"
#include "io/image/png_file.h"

namespace rt {

int run_merge(const MergeCommand& cmd) {
  std::string error;
  const std::optional<OutputKind> kind = output_kind(cmd.output, error);
  if (!kind || (*kind != OutputKind::kPng && *kind != OutputKind::kExr)) {
    std::fprintf(stderr, "rtcli: error: merge writes one image: expected -o NAME.png or NAME.exr, found \"%s\"\n",
                 cmd.output.c_str());
    return kExitBadInput;
  }
  if (!check_new_output(cmd.output, cmd.tiles, error)) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return kExitBadInput;
  }
  std::vector<std::string> problems;
  std::optional<ExrImage> merged = merge_tiles(cmd.tiles, problems);
  if (!merged) {
    for (const std::string& p : problems) std::fprintf(stderr, "rtcli: error: merge: %s\n", p.c_str());
    std::fprintf(stderr, "rtcli: nothing written\n");
    return kExitBadInput;
  }
  if (!cmd.denoiser.empty() && !denoise_exr(*merged, cmd.denoiser, usable_cpu_count(), error)) {
    std::fprintf(stderr, "rtcli: error: merge: %s; nothing written\n", error.c_str());
    return kExitBadInput;
  }
  bool ok = false;
  if (*kind == OutputKind::kExr) {
    ok = write_exr(cmd.output, *merged, merged->full_float, error);
  } else {
    const std::optional<Rgb8Image> image = displayed(*merged, cmd.output, error);
    if (!image) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitBadInput;
    }
    if (!merged->full_float && !cmd.quiet)
      std::fprintf(stderr,
                   "rtcli: note: the tiles hold half floats; the PNG can differ from a direct render's by a "
                   "rounding step (render the tiles with --exr-float for the same bytes)\n");
    ok = write_png(cmd.output, *image, error);
  }
  if (!ok) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return kExitFailure;
  }
  if (!cmd.quiet)
    std::printf("merged %zu tiles of %dx%d into %s\n", cmd.tiles.size(), merged->width, merged->height,
                cmd.output.c_str());
  return kExitSuccess;
}

}  // namespace rt
