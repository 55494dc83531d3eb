// The checks every OpenEXR file passes before OpenEXR itself sees it (docs/errors-and-limits.md).
// OpenEXR 3.1 allocates what a file declares before it reads it: a string attribute's declared
// size (a 792-byte file asked for 2 GB, found by the exr fuzzer), the line-offset table of the data
// window's height, and the whole frame buffer; and it decodes a chunk as often as the offset table
// points at it (a 6.5 KB tile whose table points every entry at one chunk decoded 2.1 GB). So the
// bytes are walked here first, in memory:
//   - one part of scanlines (what rtcli writes and environment images are), no tiles or deep data;
//   - every attribute inside the file; both windows within the pixel limit;
//   - channels x pixels within the value limit (what the reader holds as floats);
//   - the offset table inside the file, each chunk once, inside the file, no two overlapping,
//     and, for the compressions whose ratio is bounded (none, RLE, ZIP), no chunk that would
//     decode to more than that ratio times its bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rt {

struct ExrLimits {
  uint64_t max_pixels = 0;  // of the display window and of the data window
  uint64_t max_values = 0;  // channels x data-window pixels
};

struct ExrStructure {
  int channels = 0;
  uint64_t window_pixels = 0;  // the data window's
};

// Whether `bytes` (a whole file) pass the checks above; else false with `why` (one phrase, no
// file name) set.
bool check_exr_structure(const std::vector<unsigned char>& bytes, const ExrLimits& limits, ExrStructure& out,
                         std::string& why);

// The most bytes an OpenEXR file within `limits` can hold: its values as 32-bit floats, uncompressed,
// and room for the header and offset table. Files are read whole, up to this.
uint64_t max_exr_file_bytes(const ExrLimits& limits);

}  // namespace rt
