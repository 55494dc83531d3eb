#include "core/frame_scenes.h"

#include <chrono>

namespace rt {

const Scene& FrameScenes::at(int frame) {
  if (frame == built_frame_) return built_;
  const auto start = std::chrono::steady_clock::now();
  current_.reset();  // the previous frame's top level goes before the next is built
  current_ = graph_.at(graph_.pose(frame), options_);
  placing_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return *current_;
}

}  // namespace rt
