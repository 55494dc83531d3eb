#include "io/image/exr_file.h"

#include <Imath/half.h>
#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <fstream>
#include <stdexcept>

#include "io/base/atomic_file.h"
#include "io/base/input_file.h"
#include "io/image/exr_structure.h"

namespace rt {
namespace {

// OpenEXR writes to a stream; ours keeps the bytes for write_file_atomically.
class MemoryStream final : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (position_ + static_cast<uint64_t>(n) > bytes_.size()) bytes_.resize(position_ + static_cast<uint64_t>(n));
    std::memcpy(bytes_.data() + position_, c, static_cast<size_t>(n));
    position_ += static_cast<uint64_t>(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = pos; }
  std::vector<uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
  uint64_t position_ = 0;
};

// OpenEXR reads from a stream; ours serves the bytes already read and checked (exr_structure.h).
class MemoryInput final : public Imf::IStream {
 public:
  MemoryInput(const std::vector<unsigned char>& bytes, const std::string& name)
      : Imf::IStream(name.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || static_cast<uint64_t>(n) > bytes_.size() - position_)
      throw std::runtime_error("unexpected end of file");
    std::memcpy(c, bytes_.data() + position_, static_cast<size_t>(n));
    position_ += static_cast<uint64_t>(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t pos) override { position_ = std::min<uint64_t>(pos, bytes_.size()); }

 private:
  const std::vector<unsigned char>& bytes_;
  uint64_t position_ = 0;
};

ExrLimits limits_for(uint64_t max_pixels) { return ExrLimits{max_pixels, max_pixels * kMaxExrValuesPerPixel}; }

// The whole file, through the one bounded reader (no FIFO, device or folder; at most what a file
// within the limits can hold), then its structure checked.
std::optional<std::vector<unsigned char>> checked_bytes(const std::string& path, const ExrLimits& limits,
                                                        std::string& error) {
  std::string why;
  auto bytes = read_input_bytes(path, max_exr_file_bytes(limits), why);
  if (!bytes) {
    error = path + ": " + why;
    return std::nullopt;
  }
  ExrStructure structure;
  if (!check_exr_structure(*bytes, limits, structure, why)) {
    error = path + ": not a readable OpenEXR image (" + why + ")";
    return std::nullopt;
  }
  return bytes;
}

std::string channel_name(const ExrLayer& layer, const std::string& channel) {
  return layer.name.empty() ? channel : layer.name + "." + channel;
}

}  // namespace

const ExrLayer* ExrImage::layer(const std::string& name) const {
  for (const ExrLayer& l : layers)
    if (l.name == name) return &l;
  return nullptr;
}

bool write_exr(const std::string& path, const ExrImage& image, bool full_float, std::string& error) {
  const PixelWindow& w = image.window;
  if (w.empty() || !w.inside(image.width, image.height)) {
    error = path + ": the pixels to write lie outside the image";
    return false;
  }
  try {
    Imf::Header header(Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(image.width - 1, image.height - 1)),
                       Imath::Box2i(Imath::V2i(w.x0, w.y0), Imath::V2i(w.x1 - 1, w.y1 - 1)));
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& [key, value] : image.attributes) header.insert(key, Imf::StringAttribute(value));
    Imf::FrameBuffer frame;
    const size_t pixels = static_cast<size_t>(w.pixels());
    // Half channels are converted here (round to nearest): OpenEXR writes a slice as its own type.
    std::vector<std::vector<Imath::half>> halves;
    halves.reserve(image.layers.size());
    for (const ExrLayer& layer : image.layers) {
      const size_t n = layer.channels.size();
      if (layer.values.size() != pixels * n) {
        error = path + ": layer \"" + layer.name + "\" has the wrong number of values";
        return false;
      }
      const bool floats = full_float || layer.exact;
      if (!floats) halves.emplace_back(layer.values.begin(), layer.values.end());
      for (size_t c = 0; c < n; ++c) {
        header.channels().insert(channel_name(layer, layer.channels[c]), Imf::Channel(floats ? Imf::FLOAT : Imf::HALF));
        // OpenEXR addresses a slice by the data window's absolute coordinates (Slice::Make).
        frame.insert(
            channel_name(layer, layer.channels[c]),
            floats ? Imf::Slice::Make(Imf::FLOAT, layer.values.data() + c, header.dataWindow(), sizeof(float) * n,
                                      sizeof(float) * n * static_cast<size_t>(w.width()))
                   : Imf::Slice::Make(Imf::HALF, halves.back().data() + c, header.dataWindow(), sizeof(Imath::half) * n,
                                      sizeof(Imath::half) * n * static_cast<size_t>(w.width())));
      }
    }
    MemoryStream stream;
    {
      Imf::OutputFile file(stream, header, 1);  // one thread: the bytes never depend on scheduling
      file.setFrameBuffer(frame);
      file.writePixels(w.height());
    }
    return write_file_atomically(path, stream.bytes(), error);
  } catch (const std::exception& e) {
    error = path + ": OpenEXR could not write it: " + e.what();
    return false;
  }
}

std::optional<ExrImage> read_exr(const std::string& path, uint64_t max_pixels, std::string& error) {
  const auto bytes = checked_bytes(path, limits_for(max_pixels), error);
  if (!bytes) return std::nullopt;
  try {
    MemoryInput stream(*bytes, path);
    Imf::InputFile file(stream, 1);
    if (!file.isComplete()) {
      error = path + ": incomplete (its pixels end early)";
      return std::nullopt;
    }
    const Imf::Header& header = file.header();
    const Imath::Box2i display = header.displayWindow(), data = header.dataWindow();
    ExrImage image;
    image.width = display.max.x - display.min.x + 1;
    image.height = display.max.y - display.min.y + 1;
    image.window = PixelWindow{data.min.x, data.min.y, data.max.x + 1, data.max.y + 1};
    if (display.min.x != 0 || display.min.y != 0 || image.width <= 0 || image.height <= 0 ||
        static_cast<uint64_t>(image.width) * static_cast<uint64_t>(image.height) > max_pixels || image.window.empty() ||
        !image.window.inside(image.width, image.height)) {
      error = path + ": expected an image of at most " + std::to_string(max_pixels) +
              " pixels whose data window lies in its display window from (0, 0)";
      return std::nullopt;
    }
    for (auto it = header.begin(); it != header.end(); ++it)
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        image.attributes[it.name()] = s->value();
    // A few layers of a few channels each is what rtcli writes; a file of thousands would need
    // their count times the pixels in memory.
    int channels = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) ++channels;
    if (channels > kMaxExrChannels) {
      error = path + ": " + std::to_string(channels) + " channels, more than the " + std::to_string(kMaxExrChannels) +
              " rtcli reads";
      return std::nullopt;
    }
    // Channels grouped into layers by the prefix before the last '.'.
    bool float_channels = false, half_channels = false;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
      const std::string full = it.name();
      const size_t dot = full.rfind('.');
      const std::string layer = dot == std::string::npos ? "" : full.substr(0, dot);
      const std::string channel = dot == std::string::npos ? full : full.substr(dot + 1);
      if (it.channel().xSampling != 1 || it.channel().ySampling != 1) {
        error = path + ": channel " + full + " is subsampled; rtcli reads full-resolution channels";
        return std::nullopt;
      }
      const bool is_float = it.channel().type == Imf::FLOAT;
      if (is_float) float_channels = true;
      else half_channels = true;
      ExrLayer* target = nullptr;
      for (ExrLayer& l : image.layers)
        if (l.name == layer) target = &l;
      if (!target) target = &image.layers.emplace_back(ExrLayer{layer, {}, {}, true});
      target->channels.push_back(channel);
      target->exact = target->exact && is_float;
    }
    // The colour first, its channels in R, G, B order (OpenEXR lists channels alphabetically).
    for (ExrLayer& l : image.layers) {
      if (l.name.empty()) {
        std::vector<std::string> rgb;
        for (const char* c : {"R", "G", "B"})
          if (std::find(l.channels.begin(), l.channels.end(), c) != l.channels.end()) rgb.emplace_back(c);
        for (const std::string& c : l.channels)
          if (std::find(rgb.begin(), rgb.end(), c) == rgb.end()) rgb.push_back(c);
        l.channels = rgb;
      }
    }
    image.full_float = float_channels && !half_channels;
    std::stable_partition(image.layers.begin(), image.layers.end(), [](const ExrLayer& l) { return l.name.empty(); });
    const PixelWindow& w = image.window;
    Imf::FrameBuffer frame;
    for (ExrLayer& l : image.layers) {
      const size_t n = l.channels.size();
      l.values.assign(static_cast<size_t>(w.pixels()) * n, 0.0f);
      for (size_t c = 0; c < n; ++c) {
        frame.insert(channel_name(l, l.channels[c]),
                     Imf::Slice::Make(Imf::FLOAT, l.values.data() + c, data, sizeof(float) * n,
                                      sizeof(float) * n * static_cast<size_t>(w.width())));
      }
    }
    file.setFrameBuffer(frame);
    file.readPixels(data.min.y, data.max.y);
    return image;
  } catch (const std::exception& e) {
    error = path + ": not a readable OpenEXR image (" + e.what() + ")";
    return std::nullopt;
  }
}

std::optional<ExrImage> read_exr_rgb(const std::vector<unsigned char>& bytes, const std::string& name,
                                     uint64_t max_pixels, std::string& error) {
  ExrStructure structure;
  std::string why;
  // Colour is read as RGBA halves: 4 values a pixel, whatever the file's channels.
  if (!check_exr_structure(bytes, ExrLimits{max_pixels, max_pixels * 4}, structure, why)) {
    error = "not a readable OpenEXR image (" + why + ")";
    return std::nullopt;
  }
  try {
    MemoryInput stream(bytes, name);
    Imf::RgbaInputFile file(stream, 1);
    const Imath::Box2i window = file.dataWindow();
    const long width = static_cast<long>(window.max.x) - window.min.x + 1;
    const long height = static_cast<long>(window.max.y) - window.min.y + 1;
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    file.setFrameBuffer(&pixels[0][0] - window.min.x - static_cast<long>(window.min.y) * width, 1,
                        static_cast<size_t>(width));
    file.readPixels(window.min.y, window.max.y);
    ExrImage image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.window = PixelWindow{0, 0, image.width, image.height};
    ExrLayer& color = image.layers.emplace_back(ExrLayer{"", {"R", "G", "B"}, {}});
    color.values.reserve(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    for (long y = 0; y < height; ++y)
      for (long x = 0; x < width; ++x) {
        const Imf::Rgba& p = pixels[y][x];
        for (const Imath::half h : {p.r, p.g, p.b}) color.values.push_back(static_cast<float>(h));
      }
    return image;
  } catch (const std::exception& e) {
    error = std::string("OpenEXR could not read it: ") + e.what();
    return std::nullopt;
  }
}

}  // namespace rt
