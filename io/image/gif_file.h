// Animated GIF output with giflib: each frame gets its own palette (io/image/color_quantiser.h),
// frames loop for ever (the NETSCAPE2.0 extension every browser honours), and the file is
// written like PNGs: to a temporary name, then renamed into place (io/base/atomic_file.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "io/image/rgb8_image.h"

namespace rt {

// Frame delays in hundredths of a second (GIF's unit) for `frames` frames at `fps`: each frame
// ends at the rounded time of its successor's start, so 30 fps gives 3, 4, 3, 3, 4, 3, ... and
// the loop lasts exactly frames / fps seconds, to the hundredth.
// A GIF frame's delay is 16 bits of hundredths of a second: at most 655.35 s. The slowest frame
// rate rtcli writes, 500 s a frame, keeps every delay inside that (0.001 fps wrapped to 344.6 s).
inline constexpr double kMinGifFps = 0.002;
inline constexpr int kMaxGifDelay = 65535;
std::vector<int> gif_frame_delays(int frames, float fps);

class GifWriter {
 public:
  GifWriter(int width, int height, bool dither);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  // Appends a frame of the writer's size, shown for `delay` hundredths of a second.
  bool add_frame(const Rgb8Image& image, int delay, std::string& error);
  // Ends the file and writes it to `path`; nothing is written if any frame failed.
  bool finish(const std::string& path, std::string& error);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// What a GIF file holds, read back with giflib: for tests and `rtcli` users' checks.
struct GifSummary {
  int width = 0, height = 0;
  int frames = 0;
  std::vector<int> delays;  // per frame, hundredths of a second
  bool loops = false;       // has the NETSCAPE2.0 looping extension
  std::vector<Rgb8Image> images;
};
bool read_gif(const std::string& path, GifSummary& out, std::string& error);

}  // namespace rt
