#include "io/image/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <Imath/half.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <exception>

#include "io/image/atomic_file.h"

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

// OpenEXR 3.1 allocates what a header declares before it reads it: a string attribute's size (a
// 792-byte file asked for 2 GB, found by the exr fuzzer), the line-offset table of the data
// window's height. The header is walked here first: every attribute must fit in the file, and the
// windows in the pixel limit; one part of scanlines (what rtcli writes), no tiles or deep data.
bool header_fits(const std::string& path, uint64_t max_pixels, std::string& error) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) {
    error = path + ": cannot be read";
    return false;
  }
  const uint64_t file_size = static_cast<uint64_t>(in.tellg());
  std::vector<unsigned char> bytes(static_cast<size_t>(std::min<uint64_t>(file_size, uint64_t{1} << 22)));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  const auto bad = [&](const std::string& why) {
    error = path + ": not a readable OpenEXR image (" + why + ")";
    return false;
  };
  const auto u32 = [&](size_t at) {
    return static_cast<uint32_t>(bytes[at]) | static_cast<uint32_t>(bytes[at + 1]) << 8 |
           static_cast<uint32_t>(bytes[at + 2]) << 16 | static_cast<uint32_t>(bytes[at + 3]) << 24;
  };
  if (bytes.size() < 8 || u32(0) != 20000630u) return bad("no OpenEXR signature");
  const uint32_t flags = u32(4);
  if (flags & 0x1a00u) return bad("tiled, multi-part or deep; rtcli reads the single-part scanline images it writes");
  size_t at = 8;
  const auto text = [&](std::string& out) {
    const size_t start = at;
    while (at < bytes.size() && bytes[at] != 0) ++at;
    if (at >= bytes.size() || at - start > 255) return false;
    out.assign(bytes.begin() + static_cast<std::ptrdiff_t>(start), bytes.begin() + static_cast<std::ptrdiff_t>(at));
    ++at;
    return true;
  };
  bool data_window = false, display_window = false;
  while (true) {
    if (at >= bytes.size()) return bad("its header ends early");
    if (bytes[at] == 0) break;  // the end of the header
    std::string name, type;
    if (!text(name) || !text(type) || at + 4 > bytes.size()) return bad("its header ends early");
    const uint32_t size = u32(at);
    at += 4;
    if (size > file_size - at || at + size > bytes.size()) return bad("attribute " + name + " is larger than the file");
    if ((name == "dataWindow" || name == "displayWindow") && type == "box2i" && size == 16) {
      const auto i32 = [&](size_t k) { return static_cast<int64_t>(static_cast<int32_t>(u32(at + 4 * k))); };
      const int64_t w = i32(2) - i32(0) + 1, h = i32(3) - i32(1) + 1;
      if (w < 1 || h < 1 || static_cast<uint64_t>(w) * static_cast<uint64_t>(h) > max_pixels)
        return bad(name + " of " + std::to_string(w) + "x" + std::to_string(h) + " pixels, more than " +
                   std::to_string(max_pixels));
      (name == "dataWindow" ? data_window : display_window) = true;
    }
    at += size;
  }
  if (!data_window || !display_window) return bad("no dataWindow or displayWindow");
  return true;
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
    const Imf::PixelType type = full_float ? Imf::FLOAT : Imf::HALF;
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
      if (!full_float) halves.emplace_back(layer.values.begin(), layer.values.end());
      for (size_t c = 0; c < n; ++c) {
        header.channels().insert(channel_name(layer, layer.channels[c]), Imf::Channel(type));
        // OpenEXR addresses a slice by the data window's absolute coordinates (Slice::Make).
        frame.insert(channel_name(layer, layer.channels[c]),
                     full_float ? Imf::Slice::Make(Imf::FLOAT, layer.values.data() + c, header.dataWindow(),
                                                   sizeof(float) * n, sizeof(float) * n * static_cast<size_t>(w.width()))
                                : Imf::Slice::Make(Imf::HALF, halves.back().data() + c, header.dataWindow(),
                                                   sizeof(Imath::half) * n,
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
  if (!header_fits(path, max_pixels, error)) return std::nullopt;
  try {
    Imf::InputFile file(path.c_str(), 1);
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
        static_cast<uint64_t>(image.width) * static_cast<uint64_t>(image.height) > max_pixels ||
        image.window.empty() || !image.window.inside(image.width, image.height)) {
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
      if (it.channel().type == Imf::FLOAT) float_channels = true;
      else half_channels = true;
      ExrLayer* target = nullptr;
      for (ExrLayer& l : image.layers)
        if (l.name == layer) target = &l;
      if (!target) target = &image.layers.emplace_back(ExrLayer{layer, {}, {}});
      target->channels.push_back(channel);
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

bool exr_is_complete(const std::string& path) {
  std::string error;
  if (!header_fits(path, uint64_t{1} << 26, error)) return false;  // kMaxPixels: io does not see render settings
  try {
    Imf::InputFile file(path.c_str(), 1);
    return file.isComplete();
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace rt
