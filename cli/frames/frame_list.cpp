#include "cli/frames/frame_list.h"

#include <algorithm>
#include <cstdlib>

#include "cli/common/decimal.h"

namespace rt {
namespace {

// One item: "N", "A-B" or "A-BxS". The separating '-' is the first after the first character
// (which may be a sign).
bool add_item(const std::string& item, std::vector<int>& out, std::string& error) {
  const auto bad = [&](const std::string& why) {
    error = "\"" + item + "\": " + why;
    return false;
  };
  const size_t dash = item.find('-', 1);
  const size_t x = item.find('x');
  if (dash == std::string::npos) {
    if (x != std::string::npos) return bad("a step (xS) goes with a range A-BxS");
    const auto n = parse_decimal(item);
    if (!n) return bad("expected a whole number");
    if (std::labs(*n) > kMaxFrameNumber) return bad("expected a frame within +-" + std::to_string(kMaxFrameNumber));
    out.push_back(static_cast<int>(*n));
    return true;
  }
  const auto a = parse_decimal(item.substr(0, dash));
  const auto b = parse_decimal(item.substr(dash + 1, x == std::string::npos ? std::string::npos : x - dash - 1));
  const auto step = x == std::string::npos ? std::optional<long>(1) : parse_decimal(item.substr(x + 1));
  if (!a || !b) return bad("expected a range A-B of whole numbers");
  if (!step || *step < 1) return bad("expected a step of at least 1 after 'x'");
  if (std::labs(*a) > kMaxFrameNumber || std::labs(*b) > kMaxFrameNumber)
    return bad("expected frames within +-" + std::to_string(kMaxFrameNumber));
  if (*b < *a) return bad("expected A <= B");
  if (static_cast<size_t>((*b - *a) / *step + 1) + out.size() > kMaxFrameCount)
    return bad("more than " + std::to_string(kMaxFrameCount) + " frames");
  for (long f = *a; f <= *b; f += *step) out.push_back(static_cast<int>(f));
  return true;
}

}  // namespace

FrameList FrameList::range(int first, int last) {
  FrameList list;
  for (int f = first; f <= last; ++f) list.frames.push_back(f);
  return list;
}

std::string FrameList::text() const {
  std::string out;
  size_t i = 0;
  while (i < frames.size()) {
    // The longest run from i with one step; a stepped run stops before a frame that begins a
    // run of consecutive frames ("1,5,9-12", not "1-9x4,10-12").
    size_t j = i + 1;
    const int step = j < frames.size() ? frames[j] - frames[i] : 1;
    const auto starts_consecutive = [&](size_t k) { return k + 1 < frames.size() && frames[k + 1] - frames[k] == 1; };
    while (j < frames.size() && frames[j] - frames[j - 1] == step && (step == 1 || !starts_consecutive(j))) ++j;
    if (!out.empty()) out += ",";
    if (j - i >= 3 || (j - i == 2 && step == 1)) {
      out += std::to_string(frames[i]) + "-" + std::to_string(frames[j - 1]);
      if (step != 1) out += "x" + std::to_string(step);
      i = j;
    } else {
      out += std::to_string(frames[i]);
      ++i;
    }
  }
  return out;
}

FrameList FrameList::chunk(int index, int shares) const {
  const size_t n = frames.size(), k = static_cast<size_t>(std::max(1, shares)), i = static_cast<size_t>(index);
  const size_t begin = i * (n / k) + std::min(i, n % k);
  const size_t size = n / k + (i < n % k ? 1 : 0);
  FrameList out;
  out.frames.assign(frames.begin() + static_cast<std::ptrdiff_t>(std::min(begin, n)),
                    frames.begin() + static_cast<std::ptrdiff_t>(std::min(begin + size, n)));
  return out;
}

std::optional<FrameList> parse_frame_list(const std::string& text, std::string& error) {
  FrameList list;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!add_item(item, list.frames, error)) return std::nullopt;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  std::sort(list.frames.begin(), list.frames.end());
  list.frames.erase(std::unique(list.frames.begin(), list.frames.end()), list.frames.end());
  return list;
}

}  // namespace rt
