#include "cli/encode_command.h"

#include <cstdio>
#include <cstdlib>

#include "cli/exit_codes.h"
#include "cli/exr_display.h"
#include "cli/frame_output.h"
#include "cli/output_checks.h"
#include "core/render_settings.h"
#include "io/image/png_file.h"

namespace rt {

int run_encode(const EncodeCommand& cmd) {
  std::string error;
  const std::optional<OutputKind> kind = output_kind(cmd.output, error);
  if (!kind || *kind != OutputKind::kGif) {
    std::fprintf(stderr, "rtcli: error: encode writes an animated GIF: expected -o NAME.gif, found \"%s\"\n",
                 cmd.output.c_str());
    return kExitBadInput;
  }
  if (!check_new_output(cmd.output, cmd.frames, error)) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return kExitBadInput;
  }
  std::optional<float> fps = cmd.fps;
  std::optional<FrameSink> gif;  // the same writer and frame delays as rtcli render -o NAME.gif
  int width = 0, height = 0;
  for (size_t i = 0; i < cmd.frames.size(); ++i) {
    const std::string& path = cmd.frames[i];
    std::optional<Rgb8Image> image;
    const std::optional<OutputKind> frame_kind = output_kind(path, error);
    if (frame_kind && is_exr(*frame_kind)) {
      const std::optional<ExrImage> exr = read_exr(path, kMaxPixels, error);
      if (exr) {
        if (!fps)
          if (const auto it = exr->attributes.find("rtcli:fps"); it != exr->attributes.end())
            fps = std::strtof(it->second.c_str(), nullptr);
        image = displayed(*exr, path, error);
      }
    } else if (frame_kind && (*frame_kind == OutputKind::kPng || *frame_kind == OutputKind::kPngSequence)) {
      image = read_png(path, error);
    } else {
      error = "expected rendered frames, .png or .exr, found \"" + path + "\"";
    }
    if (!image) {
      std::fprintf(stderr, "rtcli: error: %s\nrtcli: nothing written\n", error.c_str());
      return kExitBadInput;
    }
    if (!gif) {
      width = image->width;
      height = image->height;
      if (!fps || !(*fps > 0.0f)) fps = 24.0f;
      gif.emplace(OutputKind::kGif, cmd.output, width, height, *fps, static_cast<int>(cmd.frames.size()), cmd.dither, 1u);
    } else if (image->width != width || image->height != height) {
      std::fprintf(stderr, "rtcli: error: %s is %dx%d, the frames before it %dx%d\nrtcli: nothing written\n",
                   path.c_str(), image->width, image->height, width, height);
      return kExitBadInput;
    }
    if (!gif->add(*image, static_cast<int>(i), error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitFailure;
    }
  }
  if (!gif->finish(error)) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return kExitFailure;
  }
  if (!cmd.quiet)
    std::printf("encoded %zu frames of %dx%d at %g fps into %s\n", cmd.frames.size(), width, height,
                static_cast<double>(*fps), cmd.output.c_str());
  return kExitSuccess;
}

}  // namespace rt
