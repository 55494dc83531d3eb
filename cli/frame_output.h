// Where rendered frames go: one PNG (or JPEG), a numbered PNG sequence (Blender's convention: the run of
// '#' in "frame_####.png" becomes the frame number, zero-padded to its length), or an animated
// GIF. The frames' syntax is cli/frame_list.h.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/image/gif_file.h"
#include "io/image/rgb8_image.h"

namespace rt {

enum class OutputKind { kPng, kPngSequence, kGif, kJpeg };

// What the file name asks for (.gif, .jpg or .jpeg, or .png with or without a run of '#'), or an error.
std::optional<OutputKind> output_kind(const std::string& path, std::string& error);

// "out/frame_####.png", 7 -> "out/frame_0007.png"; more digits than '#'s are written in full.
// Negative frames get a leading '-'.
std::string sequence_path(const std::string& pattern, int frame);

// Receives the frames of one render in order and writes them: a PNG at once per frame, the GIF
// when all frames are in. Every file goes through a temporary name and a rename.
class FrameSink {
 public:
  FrameSink(OutputKind kind, std::string path, int width, int height, float fps, int frames, bool dither,
            unsigned threads);
  bool add(const Rgb8Image& image, int frame, std::string& error);
  bool finish(std::string& error);
  // Every file written so far (or, for a GIF, the one file once finished).
  const std::vector<std::string>& written() const { return written_; }

 private:
  OutputKind kind_;
  std::string path_;
  unsigned threads_;
  std::vector<int> delays_;
  size_t added_ = 0;
  std::unique_ptr<GifWriter> gif_;
  std::vector<std::string> written_;
};

}  // namespace rt
