// Where rendered frames go: one PNG (or JPEG) or OpenEXR, a numbered PNG or EXR sequence (Blender's
// convention: the run of '#' in "frame_####.png" becomes the frame number, zero-padded to its
// length), or an animated GIF. The frames' syntax is cli/frames/frame_list.h.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/image/exr_file.h"
#include "io/image/gif_file.h"
#include "io/image/rgb8_image.h"

namespace rt {

enum class OutputKind { kPng, kPngSequence, kGif, kJpeg, kExr, kExrSequence };

inline bool is_exr(OutputKind k) { return k == OutputKind::kExr || k == OutputKind::kExrSequence; }
inline bool is_sequence(OutputKind k) { return k == OutputKind::kPngSequence || k == OutputKind::kExrSequence; }
// One image, not several frames.
inline bool is_single_image(OutputKind k) {
  return k == OutputKind::kPng || k == OutputKind::kJpeg || k == OutputKind::kExr;
}

// What the file name asks for (.gif, .jpg or .jpeg, or .png or .exr with or without a run of '#'), or an error.
std::optional<OutputKind> output_kind(const std::string& path, std::string& error);

// "out/frame_####.png", 7 -> "out/frame_0007.png"; more digits than '#'s are written in full.
// Negative frames get a leading '-'.
std::string sequence_path(const std::string& pattern, int frame);

// What an EXR output must be to count as done (--skip-existing): its metadata (render_attributes)
// and layers as this render would write them.
struct ExpectedExr {
  std::map<std::string, std::string> attributes;
  std::vector<std::string> layers;  // beside the colour, in any order
  bool full_float = false;
};

// Whether `path` holds a whole output of that kind (--skip-existing): a PNG that decodes; an EXR
// whose pixels all decode and that this render would write (`exr`: the same scene and settings
// hashes, frame, crop, tile, layers and precision); a GIF or JPEG that exists (rtcli writes every
// file whole, by renaming). An EXR from another render is not complete: it is rendered again.
bool output_is_complete(const std::string& path, OutputKind kind, const ExpectedExr& exr);

// Receives the frames of one render in order and writes them: a PNG at once per frame, the GIF
// when all frames are in. Every file goes through a temporary name and a rename.
class FrameSink {
 public:
  FrameSink(OutputKind kind, std::string path, int width, int height, float fps, int frames, bool dither,
            unsigned threads);
  bool add(const Rgb8Image& image, int frame, std::string& error);
  // A rendered frame, linear, shown through `display` or, when given, an OpenColorIO view
  // (encode_display8). A PNG's rows are encoded as its bands are compressed, with no 8-bit copy
  // of the whole image (srgb8_rows); the bytes are the same.
  bool add(const Image& linear, const DisplayTransform& display, const ViewTransform* view, int frame,
           std::string& error);
  // An EXR output's frame (half floats unless `full_float`).
  bool add_exr(const ExrImage& image, int frame, bool full_float, std::string& error);
  OutputKind kind() const { return kind_; }
  bool finish(std::string& error);
  // Every file written so far (or, for a GIF, the one file once finished).
  const std::vector<std::string>& written() const { return written_; }

 private:
  // Frame `frame`'s file: the sequence's numbered name, or the one file.
  std::string frame_path(int frame) const { return is_sequence(kind_) ? sequence_path(path_, frame) : path_; }

  OutputKind kind_;
  std::string path_;
  unsigned threads_;
  std::vector<int> delays_;
  size_t added_ = 0;
  std::unique_ptr<GifWriter> gif_;
  std::vector<std::string> written_;
};

}  // namespace rt
