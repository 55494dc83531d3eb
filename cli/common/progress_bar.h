// A one-line progress display on a terminal: bar, percentage, ETA and ray throughput, redrawn
// in place. pbrt-v4 and Mitsuba write their own too: Debian has no C++ progress-bar library.
#pragma once

#include <cstdio>
#include <string>

#include "core/render/renderer.h"

namespace rt {

class ProgressBar {
 public:
  explicit ProgressBar(std::FILE* out) : out_(out) {}
  void update(const RenderProgress& p);
  void set_label(std::string label) { label_ = std::move(label); }  // shown after the bar: "frame 3/120"
  void clear();                                                     // erase the line, ready for the summary

 private:
  std::FILE* out_;
  std::string last_;
  std::string label_;
};

// "1:05" or "0:07" (minutes:seconds), "1:02:03" past an hour.
std::string format_duration(double seconds);
// "3.41 M", "512.0 k", "12": a count with an SI prefix.
std::string format_count(double count);
// Every ray kind with its count: "1.23 M camera, 2.40 M shadow, 0 reflection, ...".
std::string format_ray_counts(const RayCounters& rays);

}  // namespace rt
