#include "cli/frames/frame_output.h"

#include <algorithm>
#include <filesystem>

#include "cli/frames/render_metadata.h"
#include "core/render_settings.h"
#include "io/image/jpeg_file.h"
#include "io/image/png_file.h"

namespace rt {
std::optional<OutputKind> output_kind(const std::string& path, std::string& error) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string name = std::filesystem::path(path).filename().string();
  if (ext == ".gif") return OutputKind::kGif;
  if (ext == ".jpg" || ext == ".jpeg") return OutputKind::kJpeg;
  if (ext == ".png") return name.find('#') != std::string::npos ? OutputKind::kPngSequence : OutputKind::kPng;
  if (ext == ".exr") return name.find('#') != std::string::npos ? OutputKind::kExrSequence : OutputKind::kExr;
  error =
      "expected an output file name ending in .png, .exr or .jpg (or frame_####.png or frame_####.exr, or .gif "
      "for animations), found \"" +
      path + "\"";
  return std::nullopt;
}

std::string sequence_path(const std::string& pattern, int frame) {
  const std::filesystem::path p(pattern);
  std::string name = p.filename().string();
  const size_t start = name.find('#');
  if (start == std::string::npos) return pattern;
  size_t end = start;
  while (end < name.size() && name[end] == '#') ++end;
  std::string digits = std::to_string(frame < 0 ? -frame : frame);
  if (digits.size() < end - start) digits.insert(0, end - start - digits.size(), '0');
  name.replace(start, end - start, (frame < 0 ? "-" : "") + digits);
  return (p.parent_path() / name).string();
}

namespace {

bool is_expected_exr(const std::string& path, const ExpectedExr& expected) {
  std::string error;
  const std::optional<ExrImage> exr = read_exr(path, kMaxPixels, error);  // every pixel decoded
  if (!exr || exr->full_float != expected.full_float) return false;
  if (!same_render(exr->attributes, expected.attributes)) return false;
  std::vector<std::string> layers, wanted = expected.layers;
  for (const ExrLayer& l : exr->layers)
    if (!l.name.empty()) layers.push_back(l.name);
  std::sort(layers.begin(), layers.end());  // OpenEXR keeps channels in name order
  std::sort(wanted.begin(), wanted.end());
  return layers == wanted;
}

}  // namespace

bool output_is_complete(const std::string& path, OutputKind kind, const ExpectedExr& exr) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) == 0) return false;
  std::string error;
  switch (kind) {
    case OutputKind::kPng:
    case OutputKind::kPngSequence: return read_png(path, error).has_value();
    case OutputKind::kExr:
    case OutputKind::kExrSequence: return is_expected_exr(path, exr);
    default: return true;
  }
}

FrameSink::FrameSink(OutputKind kind, std::string path, int width, int height, float fps, int frames, bool dither,
                     unsigned threads)
    : kind_(kind), path_(std::move(path)), threads_(threads), delays_(gif_frame_delays(frames, fps)) {
  if (kind_ == OutputKind::kGif) gif_ = std::make_unique<GifWriter>(width, height, dither);
}

bool FrameSink::add(const Rgb8Image& image, int frame, std::string& error) {
  const size_t index = added_++;
  if (kind_ == OutputKind::kGif) return gif_->add_frame(image, delays_[std::min(index, delays_.size() - 1)], error);
  const std::string path = frame_path(frame);
  if (kind_ == OutputKind::kJpeg ? !write_jpeg(path, image, error) : !write_png(path, image, error, threads_))
    return false;
  written_.push_back(path);
  return true;
}

bool FrameSink::add(const Image& linear, const DisplayTransform& display, const ViewTransform* view, int frame,
                    std::string& error) {
  if (view || (kind_ != OutputKind::kPng && kind_ != OutputKind::kPngSequence))
    return add(encode_display8(linear, display, view, threads_), frame, error);
  ++added_;
  const std::string path = frame_path(frame);
  if (!write_png(path, srgb8_rows(linear, display), error, threads_)) return false;
  written_.push_back(path);
  return true;
}

bool FrameSink::add_exr(const ExrImage& image, int frame, bool full_float, std::string& error) {
  ++added_;
  const std::string path = frame_path(frame);
  if (!write_exr(path, image, full_float, error)) return false;
  written_.push_back(path);
  return true;
}

bool FrameSink::finish(std::string& error) {
  if (kind_ != OutputKind::kGif) return true;
  if (!gif_->finish(path_, error)) return false;
  written_.push_back(path_);
  return true;
}

}  // namespace rt
