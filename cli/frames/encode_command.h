// `rtcli encode FRAME... -o OUT.gif [--fps F] [--dither]`: an animated GIF from rendered frames
// (PNG, or EXR through their display transform), in the order given: the same GIF a render of
// those frames to -o OUT.gif writes, so that frames rendered apart (rtcli render --chunk, a Slurm
// array) end as one animation. --fps defaults to the first EXR's rtcli:fps, else 24.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt {

struct EncodeCommand {
  std::vector<std::string> frames;
  std::optional<std::string> frame_list;  // --frames: frames[0] is a pattern, filled with these numbers
  std::string output;
  std::optional<float> fps;
  bool dither = false;
  bool quiet = false;
};

int run_encode(const EncodeCommand& cmd);

}  // namespace rt
