#include "io/image/gif_file.h"
#include <algorithm>

#include <gif_lib.h>

#include <cmath>
#include <cstring>

#include "io/base/atomic_file.h"
#include "io/image/color_quantiser.h"

namespace rt {

std::vector<int> gif_frame_delays(int frames, float fps) {
  std::vector<int> delays;
  // Callers refuse a rate below kMinGifFps; a NaN or slower one is taken as the slowest, so that no
  // delay can wrap or overflow.
  const double rate = fps >= kMinGifFps ? std::min(static_cast<double>(fps), 1e6) : kMinGifFps;
  const auto at = [&](int k) { return static_cast<long long>(std::llround(100.0 * k / rate)); };
  for (int k = 0; k < frames; ++k)
    delays.push_back(static_cast<int>(std::clamp<long long>(at(k + 1) - at(k), 1, kMaxGifDelay)));
  return delays;
}

struct GifWriter::State {
  int width, height;
  bool dither;
  std::vector<uint8_t> bytes;
  GifFileType* gif = nullptr;
  bool failed = false;
  std::string error;

  static int write(GifFileType* gif, const GifByteType* data, int length) {
    auto* self = static_cast<State*>(gif->UserData);
    self->bytes.insert(self->bytes.end(), data, data + length);
    return length;
  }
  bool fail(const std::string& what) {
    failed = true;
    error = "cannot encode the GIF: " + what + " (" + (gif ? GifErrorString(gif->Error) : "giflib") + ")";
    return false;
  }
};

GifWriter::GifWriter(int width, int height, bool dither) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.width = width;
  s.height = height;
  s.dither = dither;
  int code = 0;
  s.gif = EGifOpen(&s, &State::write, &code);
  if (!s.gif) {
    s.failed = true;
    s.error = std::string("cannot start a GIF: ") + GifErrorString(code);
    return;
  }
  EGifSetGifVersion(s.gif, true);  // GIF89a: delays and the looping extension
  // No global palette: each frame brings its own.
  if (EGifPutScreenDesc(s.gif, width, height, 8, 0, nullptr) == GIF_ERROR) {
    s.fail("screen descriptor");
    return;
  }
  // Loop for ever: the NETSCAPE2.0 application extension, sub-block 1, loop count 0.
  static const GifByteType kNetscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  static const GifByteType kLoopForever[] = {1, 0, 0};
  if (EGifPutExtensionLeader(s.gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(s.gif, sizeof kNetscape, kNetscape) == GIF_ERROR ||
      EGifPutExtensionBlock(s.gif, sizeof kLoopForever, kLoopForever) == GIF_ERROR ||
      EGifPutExtensionTrailer(s.gif) == GIF_ERROR)
    s.fail("looping extension");
}

GifWriter::~GifWriter() {
  if (state_->gif) EGifCloseFile(state_->gif, nullptr);
}

bool GifWriter::add_frame(const Rgb8Image& image, int delay, std::string& error) {
  State& s = *state_;
  if (s.failed) {
    error = s.error;
    return false;
  }
  if (image.width != s.width || image.height != s.height) {
    error = "a GIF frame must be " + std::to_string(s.width) + "x" + std::to_string(s.height);
    return false;
  }
  const IndexedImage indexed = quantise(image, s.dither);
  int bits = 1;
  while ((1u << bits) < indexed.palette.size()) ++bits;
  ColorMapObject* map = GifMakeMapObject(1 << bits, nullptr);
  if (!map) {
    s.fail("palette");
    error = s.error;
    return false;
  }
  std::memset(map->Colors, 0, sizeof(GifColorType) * static_cast<size_t>(map->ColorCount));
  for (size_t i = 0; i < indexed.palette.size(); ++i)
    map->Colors[i] = GifColorType{indexed.palette[i][0], indexed.palette[i][1], indexed.palette[i][2]};
  GraphicsControlBlock gcb{};
  gcb.DisposalMode = DISPOSE_DO_NOT;  // each frame covers the whole canvas
  gcb.UserInputFlag = false;
  gcb.DelayTime = delay;
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const size_t length = EGifGCBToExtension(&gcb, extension);
  bool ok = EGifPutExtension(s.gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) != GIF_ERROR &&
            EGifPutImageDesc(s.gif, 0, 0, s.width, s.height, false, map) != GIF_ERROR;
  for (int y = 0; ok && y < s.height; ++y)
    ok = EGifPutLine(s.gif,
                     const_cast<GifPixelType*>(&indexed.indices[static_cast<size_t>(y) * static_cast<size_t>(s.width)]),
                     s.width) != GIF_ERROR;
  GifFreeMapObject(map);
  if (!ok) {
    s.fail("frame");
    error = s.error;
  }
  return ok;
}

bool GifWriter::finish(const std::string& path, std::string& error) {
  State& s = *state_;
  if (s.failed) {
    error = s.error;
    return false;
  }
  int code = 0;
  const int closed = EGifCloseFile(s.gif, &code);
  s.gif = nullptr;
  if (closed == GIF_ERROR) {
    error = std::string("cannot finish the GIF: ") + GifErrorString(code);
    return false;
  }
  return write_file_atomically(path, s.bytes, error);
}

bool read_gif(const std::string& path, GifSummary& out, std::string& error) {
  int code = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &code);
  if (!gif) {
    error = "cannot open \"" + path + "\": " + GifErrorString(code);
    return false;
  }
  if (DGifSlurp(gif) == GIF_ERROR) {
    error = "cannot read \"" + path + "\": " + GifErrorString(gif->Error);
    DGifCloseFile(gif, nullptr);
    return false;
  }
  out = GifSummary{};
  out.width = gif->SWidth;
  out.height = gif->SHeight;
  out.frames = gif->ImageCount;
  for (int i = 0; i < gif->ImageCount; ++i) {
    const SavedImage& frame = gif->SavedImages[i];
    GraphicsControlBlock gcb{};
    out.delays.push_back(DGifSavedExtensionToGCB(gif, i, &gcb) == GIF_OK ? gcb.DelayTime : -1);
    for (int e = 0; e < frame.ExtensionBlockCount; ++e) {
      const ExtensionBlock& b = frame.ExtensionBlocks[e];
      if (b.Function == APPLICATION_EXT_FUNC_CODE && b.ByteCount == 11 && std::memcmp(b.Bytes, "NETSCAPE2.0", 11) == 0)
        out.loops = true;
    }
    const ColorMapObject* map = frame.ImageDesc.ColorMap ? frame.ImageDesc.ColorMap : gif->SColorMap;
    Rgb8Image image;
    image.width = frame.ImageDesc.Width;
    image.height = frame.ImageDesc.Height;
    for (int p = 0; map && p < image.width * image.height; ++p) {
      const GifColorType c = map->Colors[frame.RasterBits[p] % map->ColorCount];
      image.rgb.insert(image.rgb.end(), {c.Red, c.Green, c.Blue});
    }
    out.images.push_back(std::move(image));
  }
  DGifCloseFile(gif, nullptr);
  return true;
}

}  // namespace rt
