#include "cli/frames/encode_command.h"

#include <cstdio>
#include <cstdlib>

#include "cli/common/exit_codes.h"
#include "cli/frames/exr_display.h"
#include "cli/frames/frame_list.h"
#include "cli/frames/frame_output.h"
#include "cli/frames/output_checks.h"
#include "cli/frames/render_metadata.h"
#include "core/render_settings.h"
#include "io/image/gif_file.h"
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
  const auto bad = [](const std::string& message) {
    std::fprintf(stderr, "rtcli: error: %s\nrtcli: nothing written\n", message.c_str());
    return kExitBadInput;
  };
  if (!check_new_output(cmd.output, cmd.frames, error)) return bad(error);
  std::vector<std::string> paths = cmd.frames;
  if (cmd.frame_list) {
    // One pattern, filled with each frame number in ascending order.
    const std::optional<FrameList> list = parse_frame_list(*cmd.frame_list, error);
    if (!list) return bad("--frames: " + error);
    if (cmd.frames.size() != 1 || cmd.frames[0].find('#') == std::string::npos)
      return bad("--frames fills one NAME_####.png or NAME_####.exr pattern, found " +
                 std::to_string(cmd.frames.size()) + " frame arguments" +
                 (cmd.frames.size() == 1 ? " without '#'" : ""));
    paths.clear();
    for (const int f : list->frames) paths.push_back(sequence_path(cmd.frames[0], f));
    if (!check_new_output(cmd.output, paths, error)) return bad(error);
  }
  std::optional<float> fps = cmd.fps;
  std::optional<FrameSink> gif;  // the same writer and frame delays as rtcli render -o NAME.gif
  int width = 0, height = 0;
  for (size_t i = 0; i < paths.size(); ++i) {
    const std::string& path = paths[i];
    // Among thousands of frames, the message says which one (its number in the list, from 1).
    const std::string which = "frame " + std::to_string(i + 1) + " of " + std::to_string(paths.size()) + ", ";
    std::optional<Rgb8Image> image;
    const std::optional<OutputKind> frame_kind = output_kind(path, error);
    if (frame_kind && is_exr(*frame_kind)) {
      const std::optional<ExrImage> exr = read_exr(path, kMaxPixels, error);
      if (exr) {
        if (!fps)
          if (const auto it = exr->attributes.find(exr_key::kFps); it != exr->attributes.end()) {
            char* end = nullptr;
            const float v = std::strtof(it->second.c_str(), &end);
            if (end == it->second.c_str() || *end != 0 || !(v >= kMinGifFps && v <= 1000.0f))
              return bad(which + path + ": rtcli:fps \"" + it->second.substr(0, 40) +
                         "\": expected a frame rate from 0.002 to 1000 (or give --fps)");
            fps = v;
          }
        image = displayed(*exr, path, error);
      }
    } else if (frame_kind && (*frame_kind == OutputKind::kPng || *frame_kind == OutputKind::kPngSequence)) {
      image = read_png(path, error);
      if (!image) error = path + ": " + error;
    } else {
      error = "expected rendered frames, .png or .exr, found \"" + path + "\"";
    }
    if (!image) return bad(which + error);
    if (!gif) {
      width = image->width;
      height = image->height;
      if (!fps || !(*fps > 0.0f)) fps = 24.0f;
      gif.emplace(OutputKind::kGif, cmd.output, width, height, *fps, static_cast<int>(paths.size()), cmd.dither, 1u);
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
    std::printf("encoded %zu frames of %dx%d at %g fps into %s\n", paths.size(), width, height,
                static_cast<double>(*fps), cmd.output.c_str());
  return kExitSuccess;
}

}  // namespace rt
