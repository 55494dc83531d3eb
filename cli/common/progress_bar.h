// A one-line progress display on a terminal: bar, percentage, ETA and ray throughput, redrawn
// in place. pbrt-v4 and Mitsuba write their own too: Debian has no C++ progress-bar library.
// For a program reading rtcli's output (the Blender add-on, a farm script) the same progress as
// lines instead, "rtcli: progress 42%", one per whole percent (render --progress lines).
#pragma once

#include <cstdio>
#include <string>

#include "core/name_table.h"
#include "core/render/renderer.h"

namespace rt {

enum class ProgressStyle { kAuto, kBar, kLines, kNone };
inline constexpr NameEntry<ProgressStyle> kProgressStyleEntries[] = {
    {"auto", ProgressStyle::kAuto, "the bar where the error stream is a terminal, else nothing (default)"},
    {"bar", ProgressStyle::kBar, "a bar redrawn in place"},
    {"lines", ProgressStyle::kLines, "a line \"rtcli: progress N%\" at each whole percent, for programs"},
    {"none", ProgressStyle::kNone, "nothing"}};
inline constexpr NameTable<ProgressStyle> kProgressStyles{kProgressStyleEntries};

class ProgressBar {
 public:
  explicit ProgressBar(std::FILE* out, ProgressStyle style = ProgressStyle::kBar) : out_(out), style_(style) {}
  void update(const RenderProgress& p);
  void set_label(std::string label) { label_ = std::move(label); }  // shown after the bar: "frame 3/120"
  void clear();                                                     // erase the line, ready for the summary

 private:
  std::FILE* out_;
  ProgressStyle style_;
  int last_percent_ = -1;  // kLines: the last line's
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
