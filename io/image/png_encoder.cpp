#include "io/image/png_encoder.h"

#include <zlib.h>

#include <algorithm>
#include <vector>

#include "core/parallel_for.h"

namespace rt {
namespace {

constexpr int kRowsPerBand = 64;
constexpr int kLevel = 1;  // Z_BEST_SPEED: renders are smooth, filtering does most of the work

void put_u32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(v >> shift));
}

void put_chunk(std::vector<uint8_t>& out, const char type[4], const uint8_t* data, size_t size) {
  put_u32(out, static_cast<uint32_t>(size));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  if (size > 0) out.insert(out.end(), data, data + size);
  const uLong crc = crc32(0L, out.data() + start, static_cast<uInt>(out.size() - start));
  put_u32(out, static_cast<uint32_t>(crc));
}

struct Band {
  std::vector<uint8_t> deflated;  // raw deflate, ending on a byte boundary (or the final block)
  uLong adler = 1;                // of the band's filtered bytes
  size_t filtered_size = 0;
  bool ok = false;
};

// A worker's buffers, kept from band to band: fresh ones for each band (two of 370 KB at 1920
// pixels a row) were fresh pages, each first touch a page fault, 5% of antialias.json's wall.
struct Scratch {
  std::vector<uint8_t> row, filtered, deflated;
};

// Filters rows [y0, y1) with Sub (each byte minus the same channel of the pixel to its left)
// and deflates them; the last band finishes the stream.
void compress_band(const Rgb8Rows& rows, int y0, int y1, bool last, Scratch& scratch, Band& band) {
  const size_t row_bytes = static_cast<size_t>(rows.width) * 3;
  scratch.row.resize(row_bytes);
  std::vector<uint8_t>& filtered = scratch.filtered;
  filtered.resize(static_cast<size_t>(y1 - y0) * (row_bytes + 1));
  uint8_t* dst = filtered.data();
  for (int y = y0; y < y1; ++y) {
    const uint8_t* row = rows.row(y, scratch.row.data());
    *dst++ = 1;  // filter type Sub
    for (size_t i = 0; i < row_bytes; ++i) *dst++ = static_cast<uint8_t>(row[i] - (i >= 3 ? row[i - 3] : 0));
  }
  band.filtered_size = filtered.size();
  band.adler = adler32(1L, filtered.data(), static_cast<uInt>(filtered.size()));
  z_stream z{};
  if (deflateInit2(&z, kLevel, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return;
  std::vector<uint8_t>& out = scratch.deflated;
  out.resize(deflateBound(&z, static_cast<uLong>(filtered.size())) + 16);
  z.next_in = filtered.data();
  z.avail_in = static_cast<uInt>(filtered.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  // A sync flush ends the band on a byte boundary with a non-final block, so bands concatenate.
  const int result = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
  band.ok = last ? result == Z_STREAM_END : result == Z_OK && z.avail_in == 0;
  band.deflated.assign(out.begin(), out.end() - static_cast<std::ptrdiff_t>(z.avail_out));
  deflateEnd(&z);
}

}  // namespace

std::vector<uint8_t> encode_png(const Rgb8Image& image, unsigned threads) {
  return encode_png(rows_of(image), threads);
}

std::vector<uint8_t> encode_png(const Rgb8Rows& rows, unsigned threads) {
  const int bands = std::max(1, (rows.height + kRowsPerBand - 1) / kRowsPerBand);
  std::vector<Band> compressed(static_cast<size_t>(bands));
  std::vector<Scratch> scratch(std::max(1u, threads));
  parallel_for(static_cast<size_t>(bands), threads, 1, [&](unsigned worker, size_t item) {
    const int b = static_cast<int>(item);
    compress_band(rows, b * kRowsPerBand, std::min(rows.height, (b + 1) * kRowsPerBand), b == bands - 1,
                  scratch[worker], compressed[item]);
  });

  std::vector<uint8_t> idat{0x78, 0x01};  // zlib header: deflate, 32 KiB window, fastest
  uLong adler = 1;
  for (const Band& band : compressed) {
    if (!band.ok) return {};
    idat.insert(idat.end(), band.deflated.begin(), band.deflated.end());
    adler = adler32_combine(adler, band.adler, static_cast<z_off_t>(band.filtered_size));
  }
  put_u32(idat, static_cast<uint32_t>(adler));

  std::vector<uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<uint8_t> header;
  put_u32(header, static_cast<uint32_t>(rows.width));
  put_u32(header, static_cast<uint32_t>(rows.height));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace
  put_chunk(png, "IHDR", header.data(), header.size());
  put_chunk(png, "IDAT", idat.data(), idat.size());
  put_chunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace rt
