// What `rtcli watch` shows, in one place that its three threads share: the render thread posts
// each refinement's film (cli/watch/preview_renderer.h), the watching thread the outcome of each
// load of the scene (its problems, located, and what it kept), and the page server reads both
// (cli/watch/preview_server.h). An image is posted whole and never changed after: readers hold
// it by a shared pointer, so a slow download never blocks the render.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/render/film.h"
#include "core/tone_map.h"
#include "io/base/diagnostics.h"

namespace rt {

// One refinement of the picture: the film of a stage (the first, coarse one smaller than the
// image), and what it took.
struct PreviewImage {
  Film film;                   // with the first hit's layers
  uint64_t scene_version = 0;  // of the load it shows (PreviewStatus::scene_version)
  int width = 0;               // of the image the film previews
  int height = 0;
  int frame = 0;                   // of the scene's animation
  int samples = 0;                 // a pixel's samples so far (the path tracer's passes), or rays per pixel
  int target_samples = 0;          // the path tracer: the most a pixel takes; else 0
  std::string stage;               // "coarse", "draft", "final" or "pass"
  bool last = false;               // nothing refines it further
  double seconds = 0.0;            // since the change that made this scene version was seen
  uint64_t rays = 0;               // traced for it, since then
  bool radiance = true;            // false: a debug view (its values are data, never tone mapped)
  bool path_traced = false;        // its refinement map is the samples a pixel took
  DisplayTransform display;        // the scene's own exposure and tone map: the page's defaults
  float yaw = 0.0f, pitch = 0.0f;  // the page's orbit of the camera (0, 0: the file's)
};

// What the page polls: everything but the pixels.
struct PreviewStatus {
  uint64_t image_version = 0;  // grows with every image posted
  uint64_t scene_version = 0;  // grows with every good load
  std::shared_ptr<const PreviewImage> image;
  std::vector<Diagnostic> problems;  // of the last load (errors: the image is the last good one's)
  bool load_failed = false;
  std::string scene;                    // the file, as named
  std::string reload;                   // what the last reload did, in words
  double first_image_seconds = -1.0;    // from the change seen to this version's first image
  int first_frame = 0, last_frame = 0;  // the scene's timeline
  bool animated = false;
  double rays_per_second = 0.0;  // while rendering
  bool rendering = false;
};

class PreviewBoard {
 public:
  explicit PreviewBoard(std::string scene) { status_.scene = std::move(scene); }

  void post_image(std::shared_ptr<const PreviewImage> image) {
    const std::lock_guard lock(mutex_);
    if (image->scene_version == status_.scene_version && status_.first_image_seconds < 0.0)
      status_.first_image_seconds = image->seconds;
    status_.image = std::move(image);
    ++status_.image_version;
  }
  // A load that worked: the problems are its warnings. Returns the new scene version, which the
  // images rendered from it carry.
  uint64_t post_load(std::vector<Diagnostic> problems, std::string reload, int first_frame, int last_frame,
                     bool animated) {
    const std::lock_guard lock(mutex_);
    status_.problems = std::move(problems);
    status_.load_failed = false;
    status_.reload = std::move(reload);
    status_.first_frame = first_frame;
    status_.last_frame = last_frame;
    status_.animated = animated;
    status_.first_image_seconds = -1.0;
    return ++status_.scene_version;
  }
  // A load that failed: its problems are shown and the last good image stays.
  void post_failure(std::vector<Diagnostic> problems) {
    const std::lock_guard lock(mutex_);
    status_.problems = std::move(problems);
    status_.load_failed = true;
  }
  void post_progress(double rays_per_second, bool rendering) {
    const std::lock_guard lock(mutex_);
    status_.rays_per_second = rays_per_second;
    status_.rendering = rendering;
  }

  PreviewStatus status() const {
    const std::lock_guard lock(mutex_);
    return status_;
  }
  std::shared_ptr<const PreviewImage> image() const {
    const std::lock_guard lock(mutex_);
    return status_.image;
  }

 private:
  mutable std::mutex mutex_;
  PreviewStatus status_;
};

}  // namespace rt
