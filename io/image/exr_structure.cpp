#include "io/image/exr_structure.h"

#include <algorithm>
#include <optional>

namespace rt {
namespace {

constexpr uint32_t kMagic = 20000630u;
constexpr uint32_t kTiled = 0x200, kDeep = 0x800, kMultiPart = 0x1000;
constexpr uint64_t kMaxHeaderBytes = uint64_t{1} << 22;

// Scanlines per chunk of each compression, in OpenEXR's numbering (ImfCompression.h).
constexpr int kLinesPerChunk[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
constexpr const char* kCompressionNames[] = {"none",  "RLE", "ZIPS", "ZIP",  "PIZ",
                                             "PXR24", "B44", "B44A", "DWAA", "DWAB"};

// The most a chunk's bytes can decode to, per compressed byte, where the method bounds it: stored
// (1), RLE (a run of up to 128 bytes in 2: 64) and zlib (deflate's 1032:1, with room for the
// stream's own few bytes). 0: not bounded here (PIZ, PXR24, B44, DWA), the value limit holds.
constexpr uint64_t kMaxRatio[] = {1, 64, 1040, 1040, 0, 0, 0, 0, 0, 0};

struct Reader {
  const std::vector<unsigned char>& bytes;
  size_t at = 0;

  bool has(uint64_t n) const { return n <= bytes.size() - at; }
  uint32_t u32(size_t k) const {
    return static_cast<uint32_t>(bytes[k]) | static_cast<uint32_t>(bytes[k + 1]) << 8 |
           static_cast<uint32_t>(bytes[k + 2]) << 16 | static_cast<uint32_t>(bytes[k + 3]) << 24;
  }
  int32_t i32(size_t k) const { return static_cast<int32_t>(u32(k)); }
  uint64_t u64(size_t k) const { return static_cast<uint64_t>(u32(k)) | static_cast<uint64_t>(u32(k + 4)) << 32; }
  // A NUL-terminated name of at most 255 bytes (OpenEXR's long names).
  bool text(std::string& out) {
    const size_t start = at;
    while (at < bytes.size() && bytes[at] != 0 && at - start <= 255) ++at;
    if (at >= bytes.size() || bytes[at] != 0) return false;
    out.assign(bytes.begin() + static_cast<std::ptrdiff_t>(start), bytes.begin() + static_cast<std::ptrdiff_t>(at));
    ++at;
    return true;
  }
};

struct Box {
  int64_t x0, y0, x1, y1;
  uint64_t width() const { return static_cast<uint64_t>(x1 - x0 + 1); }
  uint64_t height() const { return static_cast<uint64_t>(y1 - y0 + 1); }
};

// The channel list's bytes per pixel of a full line, and its channel count; nullopt when malformed.
std::optional<std::pair<uint64_t, int>> channel_list(const Reader& r, size_t at, size_t end) {
  uint64_t bytes_per_pixel = 0;
  int count = 0;
  Reader c{r.bytes, at};
  while (true) {
    if (c.at >= end) return std::nullopt;
    if (r.bytes[c.at] == 0) break;
    std::string name;
    if (!c.text(name) || c.at + 16 > end) return std::nullopt;
    const uint32_t type = c.u32(c.at);
    const int32_t xs = c.i32(c.at + 8), ys = c.i32(c.at + 12);
    if (type > 2 || xs < 1 || ys < 1) return std::nullopt;
    bytes_per_pixel += type == 1 ? 2 : 4;  // half, else uint or float
    ++count;
    c.at += 16;
  }
  return std::make_pair(bytes_per_pixel, count);
}

// OpenEXR reads a value of a known type by its type, not by the size the file declares: a float
// declared 516 bytes long is read as 4, and the next 512 bytes are taken for attributes (a
// 1251-byte file so read took 1.6 GB, found by the exr fuzzer). So the declared size must be the
// type's own: fixed for the fixed types, the walk's length for the lists, w x h x 4 + 8 for a
// preview image. Types OpenEXR does not know it keeps as opaque bytes of the declared size.
std::string attribute_size_problem(const Reader& r, const std::string& type, uint32_t size) {
  static const std::pair<const char*, uint32_t> kFixed[] = {
      {"box2i", 16},      {"box2f", 16},    {"float", 4},    {"double", 8},         {"int", 4},
      {"v2i", 8},         {"v2f", 8},       {"v2d", 16},     {"v3i", 12},           {"v3f", 12},
      {"v3d", 24},        {"m33f", 36},     {"m33d", 72},    {"m44f", 64},          {"m44d", 128},
      {"compression", 1}, {"lineOrder", 1}, {"envmap", 1},   {"deepImageState", 1}, {"chromaticities", 32},
      {"rational", 8},    {"keycode", 28},  {"timecode", 8}, {"tiledesc", 9}};
  for (const auto& [name, bytes] : kFixed)
    if (type == name)
      return size == bytes ? ""
                           : "declared " + std::to_string(size) + " bytes, where it takes " + std::to_string(bytes);
  if (type == "chlist") {
    // Entries, then a NUL that must be the value's last byte.
    Reader c{r.bytes, r.at};
    const size_t end = r.at + size;
    std::string channel;
    while (c.at < end && r.bytes[c.at] != 0) {
      if (!c.text(channel) || c.at + 16 > end) return "an entry runs past its declared size";
      c.at += 16;
    }
    return c.at + 1 == end ? "" : "its end is not at its declared size";
  }
  if (type == "stringvector") {
    for (size_t at = r.at, end = r.at + size; at < end;) {
      if (end - at < 4) return "an entry runs past its declared size";
      const int32_t length = r.i32(at);
      if (length < 0 || static_cast<uint64_t>(length) > end - at - 4) return "an entry runs past its declared size";
      at += 4 + static_cast<size_t>(length);
    }
    return "";
  }
  if (type == "preview") {
    if (size < 8) return "declared " + std::to_string(size) + " bytes, fewer than its size takes";
    const uint64_t w = r.u32(r.at), h = r.u32(r.at + 4);
    return (size - 8) % 4 == 0 && w * h == (size - 8) / 4 ? ""
                                                          : "a " + std::to_string(w) + " x " + std::to_string(h) +
                                                                " preview in " + std::to_string(size) + " bytes";
  }
  return "";  // string (its size is its length) and unknown types (opaque bytes)
}

}  // namespace

uint64_t max_exr_file_bytes(const ExrLimits& limits) {
  // Values as floats (a chunk is stored raw where compression would not shrink it), the header,
  // and an offset and a chunk header per line (at most 16M lines).
  return limits.max_values * 4 + kMaxHeaderBytes + 16 * std::min<uint64_t>(limits.max_pixels, uint64_t{1} << 24);
}

bool check_exr_structure(const std::vector<unsigned char>& bytes, const ExrLimits& limits, ExrStructure& out,
                         std::string& why) {
  Reader r{bytes};
  const auto bad = [&](const std::string& what) {
    why = what;
    return false;
  };
  if (bytes.size() < 8 || r.u32(0) != kMagic) return bad("no OpenEXR signature");
  if (r.u32(4) & (kTiled | kDeep | kMultiPart))
    return bad("tiled, multi-part or deep; rtcli reads single-part scanline images");
  r.at = 8;
  std::optional<Box> data, display;
  std::optional<std::pair<uint64_t, int>> channels;
  int compression = -1;
  while (true) {
    if (r.at >= bytes.size() || r.at > kMaxHeaderBytes) return bad("its header ends early");
    if (bytes[r.at] == 0) break;
    std::string name, type;
    if (!r.text(name) || !r.text(type) || !r.has(4)) return bad("its header ends early");
    const uint32_t size = r.u32(r.at);
    r.at += 4;
    if (!r.has(size)) return bad("attribute " + name + " is larger than the file");
    if (const std::string why_not = attribute_size_problem(r, type, size); !why_not.empty())
      return bad("attribute " + name + " of type " + type + ": " + why_not);
    if ((name == "dataWindow" || name == "displayWindow") && type == "box2i" && size == 16) {
      const Box b{r.i32(r.at), r.i32(r.at + 4), r.i32(r.at + 8), r.i32(r.at + 12)};
      if (b.x1 < b.x0 || b.y1 < b.y0 || b.width() * b.height() > limits.max_pixels)
        return bad(name + " of " + std::to_string(b.x1 - b.x0 + 1) + "x" + std::to_string(b.y1 - b.y0 + 1) +
                   " pixels: expected 1 to " + std::to_string(limits.max_pixels));
      (name == "dataWindow" ? data : display) = b;
    } else if (name == "channels" && type == "chlist") {
      channels = channel_list(r, r.at, r.at + size);
      if (!channels) return bad("its channel list is malformed");
    } else if (name == "compression" && type == "compression" && size == 1) {
      compression = bytes[r.at];
      if (compression > 9) return bad("unknown compression " + std::to_string(compression));
    }
    r.at += size;
  }
  ++r.at;  // the header's final NUL
  if (!data || !display) return bad("no dataWindow or displayWindow");
  if (!channels || channels->second == 0) return bad("no channels");
  if (compression < 0) return bad("no compression attribute");
  out.channels = channels->second;
  out.window_pixels = data->width() * data->height();
  if (static_cast<uint64_t>(out.channels) * out.window_pixels > limits.max_values)
    return bad(std::to_string(out.channels) + " channels of " + std::to_string(out.window_pixels) +
               " pixels: " + std::to_string(static_cast<uint64_t>(out.channels) * out.window_pixels) +
               " values, more than the " + std::to_string(limits.max_values) + " read at most");

  // The offset table, then each chunk: its line, its size, inside the file and apart from the others.
  const uint64_t lines = data->height(), per_chunk = static_cast<uint64_t>(kLinesPerChunk[compression]);
  const uint64_t chunks = (lines + per_chunk - 1) / per_chunk;
  if (!r.has(chunks * 8))
    return bad("incomplete: its offset table of " + std::to_string(chunks) + " chunks ends early");
  const size_t table = r.at, first_byte = r.at + chunks * 8;
  struct Span {
    uint64_t begin, end;
  };
  std::vector<Span> spans;
  spans.reserve(chunks);
  std::vector<bool> seen(chunks, false);
  const uint64_t line_bytes = data->width() * channels->first;
  for (uint64_t k = 0; k < chunks; ++k) {
    const uint64_t offset = r.u64(table + 8 * k);
    if (offset < first_byte || offset > bytes.size() || bytes.size() - offset < 8)
      return bad("incomplete: chunk " + std::to_string(k) + " of " + std::to_string(chunks) +
                 " lies outside the file (cut short?)");
    const int64_t y = r.i32(offset);
    const int64_t packed = r.i32(offset + 4);
    if (y < data->y0 || y > data->y1 || (static_cast<uint64_t>(y - data->y0)) % per_chunk != 0)
      return bad("chunk " + std::to_string(k) + " names line " + std::to_string(y) + ", not the first of a chunk");
    const uint64_t index = static_cast<uint64_t>(y - data->y0) / per_chunk;
    if (seen[index]) return bad("two chunks hold line " + std::to_string(y));
    seen[index] = true;
    if (packed < 0 || static_cast<uint64_t>(packed) > bytes.size() - offset - 8)
      return bad("incomplete: chunk " + std::to_string(k) + " ends past the file (cut short?)");
    const uint64_t lines_here = std::min<uint64_t>(per_chunk, static_cast<uint64_t>(data->y1 - y + 1));
    const uint64_t raw = lines_here * line_bytes, ratio = kMaxRatio[compression];
    if (ratio != 0 && static_cast<uint64_t>(packed) < raw && raw > ratio * static_cast<uint64_t>(packed) + 1024)
      return bad("chunk " + std::to_string(k) + " would decode " + std::to_string(packed) + " bytes of " +
                 kCompressionNames[compression] + " into " + std::to_string(raw) + ", more than that method can");
    spans.push_back(Span{offset, offset + 8 + static_cast<uint64_t>(packed)});
  }
  std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.begin < b.begin; });
  for (size_t k = 1; k < spans.size(); ++k)
    if (spans[k].begin < spans[k - 1].end) return bad("two of its chunks overlap");
  return true;
}

}  // namespace rt
