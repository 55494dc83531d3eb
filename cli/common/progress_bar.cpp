#include "cli/common/progress_bar.h"

#include <algorithm>
#include <cmath>

namespace rt {

std::string format_duration(double seconds) {
  const auto total = static_cast<long long>(std::llround(std::max(0.0, seconds)));
  char buf[32];
  if (total >= 3600) std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", total / 3600, total / 60 % 60, total % 60);
  else std::snprintf(buf, sizeof buf, "%lld:%02lld", total / 60, total % 60);
  return buf;
}

std::string format_count(double count) {
  char buf[32];
  if (count >= 1e9) std::snprintf(buf, sizeof buf, "%.2f G", count / 1e9);
  else if (count >= 1e6) std::snprintf(buf, sizeof buf, "%.2f M", count / 1e6);
  else if (count >= 1e3) std::snprintf(buf, sizeof buf, "%.1f k", count / 1e3);
  else std::snprintf(buf, sizeof buf, "%.0f ", count);
  return buf;
}

std::string format_ray_counts(const RayCounters& rays) {
  std::string out;
  for (size_t k = 0; k < kRayKindCount; ++k) {
    if (k > 0) out += ", ";
    std::string n = format_count(static_cast<double>(rays.count[k]));
    if (n.back() == ' ') n.pop_back();
    out += n + " " + kRayKindNames[k];
  }
  return out;
}

void ProgressBar::update(const RenderProgress& p) {
  constexpr int kWidth = 30;
  const double fraction =
      p.pixels_total ? static_cast<double>(p.pixels_done) / static_cast<double>(p.pixels_total) : 1.0;
  if (style_ == ProgressStyle::kLines) {
    const int percent = static_cast<int>(std::floor(100.0 * std::clamp(fraction, 0.0, 1.0)));
    if (percent <= last_percent_) return;
    last_percent_ = percent;
    std::fprintf(out_, "rtcli: progress %d%%%s%s\n", percent, label_.empty() ? "" : " ", label_.c_str());
    std::fflush(out_);
    return;
  }
  const int filled = static_cast<int>(fraction * kWidth);
  std::string line = "\r[" + std::string(static_cast<size_t>(filled), '#') +
                     std::string(static_cast<size_t>(kWidth - filled), '-') + "]";
  char buf[128];
  const double eta = fraction > 0.0 ? p.seconds * (1.0 - fraction) / fraction : 0.0;
  const double rate = p.seconds > 0.0 ? static_cast<double>(p.rays) / p.seconds : 0.0;
  std::snprintf(buf, sizeof buf, " %5.1f%%  ETA %s  %srays/s", 100.0 * fraction,
                fraction > 0.0 ? format_duration(eta).c_str() : "?:??", format_count(rate).c_str());
  line += buf;
  if (!label_.empty()) line += "  " + label_;
  if (line == last_) return;
  last_ = line;
  std::fputs((line + "\x1b[K").c_str(), out_);
  std::fflush(out_);
}

void ProgressBar::clear() {
  if (last_.empty()) return;
  std::fputs("\r\x1b[K", out_);
  std::fflush(out_);
  last_.clear();
}

}  // namespace rt
