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
    const auto i = parse_decimal(*id), n = parse_decimal(*count), m = min ? parse_decimal(*min) : std::optional<long>(0);
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

std::optional<PixelWindow> parse_crop(const std::string& text, int width, int height, std::string& error) {
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
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (v.size() != 4) {
    error = "--crop: expected x0,y0,x1,y1 (four whole numbers, pixels, x1 and y1 excluded), found \"" + text + "\"";
    return std::nullopt;
  }
  const PixelWindow w{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]), static_cast<int>(v[3])};
  if (v[0] < 0 || v[1] < 0 || v[2] > width || v[3] > height || v[2] <= v[0] || v[3] <= v[1]) {
    error = "--crop: expected 0 <= x0 < x1 <= " + std::to_string(width) + " and 0 <= y0 < y1 <= " +
            std::to_string(height) + " (the image is " + size + "), found \"" + text + "\"";
    return std::nullopt;
  }
  return w;
}

}  // namespace rt
