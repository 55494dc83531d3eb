// The frames a command renders, in the syntax Blender's command line and render managers (Qube,
// Flamenco) use: "12", a range "1-120", every S-th frame of a range "1-120x10" (1, 11, ..., 111),
// and lists of these "1,5,9-12". Negative frames are allowed ("-5--1"). The frames are rendered
// in ascending order, each once.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt {

inline constexpr int kMaxFrameNumber = 1000000;   // |frame| at most this
inline constexpr size_t kMaxFrameCount = 100000;  // frames in one command

struct FrameList {
  std::vector<int> frames;  // ascending, each once; never empty once parsed

  static FrameList range(int first, int last);  // first..last
  int count() const { return static_cast<int>(frames.size()); }
  int first() const { return frames.front(); }
  int last() const { return frames.back(); }
  // The compact form: "7", "1-120", "1-111x10" or a comma list of those.
  std::string text() const;
  // Share `index` of `shares` (0-based): consecutive frames, the shares' sizes differing by at most
  // one, the earlier ones larger. Empty when there are more shares than frames and this one has none.
  FrameList chunk(int index, int shares) const;
};

// The list, or nothing with `error` saying what was expected.
std::optional<FrameList> parse_frame_list(const std::string& text, std::string& error);

}  // namespace rt
