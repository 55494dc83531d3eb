#include "cli/frames/render_share.h"

#include <cstdlib>
#include <vector>

#include "cli/common/decimal.h"

namespace rt {

EnvironmentLookup process_environment() {
  return [](const std::string& name) -> std::optional<std::string> {
    const char* v = std::getenv(name.c_str());
    return v ? std::optional<std::string>(v) : std::nullopt;
  };
}

std::optional<Share> parse_share(const std::string& text, const char* option, const EnvironmentLookup& env,
                                 std::string& error) {
  if (text == "auto") {
    const auto id = env("SLURM_ARRAY_TASK_ID"), count = env("SLURM_ARRAY_TASK_COUNT");
    const auto min = env("SLURM_ARRAY_TASK_MIN");
    if (!id || !count) {
      error = std::string(option) +
              " auto: expected a Slurm job array's SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT, found none (give "
              "I/N outside an array)";
      return std::nullopt;
    }
    const auto i = parse_decimal(*id), n = parse_decimal(*count),
               m = min ? parse_decimal(*min) : std::optional<long>(0);
    if (!i || !n || !m || *n < 1 || *i - *m < 0 || *i - *m >= *n) {
      error = std::string(option) + " auto: SLURM_ARRAY_TASK_ID " + *id + " less SLURM_ARRAY_TASK_MIN " +
              (min ? *min : std::string("0")) + " is not a task of SLURM_ARRAY_TASK_COUNT " + *count +
              " (auto expects an array of consecutive indices)";
      return std::nullopt;
    }
    return Share{static_cast<int>(*i - *m), static_cast<int>(*n)};
  }
  const size_t slash = text.find('/');
  const auto i = slash == std::string::npos ? std::nullopt : parse_decimal(text.substr(0, slash));
  const auto n = slash == std::string::npos ? std::nullopt : parse_decimal(text.substr(slash + 1));
  if (!i || !n || *n < 1 || *n > kMaxShares || *i < 0 || *i >= *n) {
    error = std::string(option) + ": expected I/N with 0 <= I < N <= " + std::to_string(kMaxShares) +
            ", or auto, found \"" + text + "\"";
    return std::nullopt;
  }
  return Share{static_cast<int>(*i), static_cast<int>(*n)};
}

std::string share_text(const Share& share) { return std::to_string(share.index) + "/" + std::to_string(share.count); }

std::optional<PixelWindow> parse_crop_text(const std::string& text, std::string& error) {
  std::vector<long> v;
  size_t start = 0;
  while (v.size() < 5) {
    const size_t comma = text.find(',', start);
    const auto n = parse_decimal(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (!n) break;
    v.push_back(*n);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  constexpr long kMost = 1L << 30;  // past any image rtcli renders (docs/errors-and-limits.md)
  if (v.size() != 4 || v[0] < 0 || v[1] < 0 || v[2] <= v[0] || v[3] <= v[1] || v[2] > kMost || v[3] > kMost) {
    error =
        "--crop: expected x0,y0,x1,y1 (four whole numbers, pixels, 0 <= x0 < x1 and 0 <= y0 < y1, x1 and y1 "
        "excluded), found \"" +
        text + "\"";
    return std::nullopt;
  }
  return PixelWindow{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]), static_cast<int>(v[3])};
}

bool crop_fits(const PixelWindow& w, int width, int height, std::string& error) {
  if (w.x1 <= width && w.y1 <= height) return true;
  error = "--crop: expected 0 <= x0 < x1 <= " + std::to_string(width) +
          " and 0 <= y0 < y1 <= " + std::to_string(height) + " (the image is " + std::to_string(width) + "x" +
          std::to_string(height) + "), found \"" + std::to_string(w.x0) + "," + std::to_string(w.y0) + "," +
          std::to_string(w.x1) + "," + std::to_string(w.y1) + "\"";
  return false;
}

}  // namespace rt
