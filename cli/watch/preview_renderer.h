// The render thread of `rtcli watch`: renders the scene it was last given, in stages that each
// post a better picture to the board (cli/watch/preview_board.h), and drops what it is doing the
// moment it is given another scene or frame. The stages:
//   coarse  a quarter of the width and height, one sample a pixel (the path tracer) or the draft
//           settings (--preview's): a first picture in a fraction of a second
//   draft   the path tracer: the whole image at one sample a pixel,
//   pass    then in passes of 8 samples a pixel, each pass posted,
//           until every pixel has its samples (or the noise threshold stopped it)
//   draft   Whitted and the debug views: the whole image with the draft settings,
//   final   then with the scene's own (when they differ).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "cli/watch/preview_board.h"
#include "core/render_settings.h"
#include "io/scene_loader.h"

namespace rt {

class PreviewRenderer {
 public:
  using Clock = std::chrono::steady_clock;

  explicit PreviewRenderer(PreviewBoard& board);
  ~PreviewRenderer();  // stops the render and joins the thread
  PreviewRenderer(const PreviewRenderer&) = delete;
  PreviewRenderer& operator=(const PreviewRenderer&) = delete;

  // Renders `scene` with `settings` from now on, at `frame`; `version` is the board's scene
  // version, `seen` when the change that led to it was seen (the images' time counts from it).
  void show(std::shared_ptr<const LoadedScene> scene, const RenderSettings& settings, uint64_t version, int frame,
            Clock::time_point seen);
  // The same scene at another frame of its animation.
  void show_frame(int frame);
  // The same scene through its camera orbited (cli/watch/orbit.h); 0, 0: the file's camera.
  // Kept for the scenes shown after it.
  void show_orbit(float yaw, float pitch);
  // The frame shown (or about to be).
  int frame() const;

 private:
  struct Job {
    std::shared_ptr<const LoadedScene> scene;
    RenderSettings settings;
    uint64_t version = 0;
    int frame = 0;
    Clock::time_point seen;
    float yaw = 0.0f, pitch = 0.0f;  // the page's orbit
  };
  void run();
  void render_job(const Job& job);
  void start(Job job);

  PreviewBoard& board_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Job> pending_;
  std::optional<Job> current_;  // the last job given (for show_frame)
  bool stopping_ = false;
  std::atomic<bool> cancel_{false};
  std::thread thread_;
};

}  // namespace rt
