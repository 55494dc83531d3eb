#include "cli/watch/preview_renderer.h"

#include <algorithm>
#include <exception>

#include "cli/watch/orbit.h"
#include "core/frame_scenes.h"
#include "core/render/integrator.h"
#include "core/render/renderer.h"
#include "core/thread_count.h"

namespace rt {
namespace {

// The coarse stage's settings: a quarter of each side, the least work a pixel can take.
RenderSettings coarse_settings(const RenderSettings& s, bool path_traced) {
  RenderSettings c = path_traced ? s : preview_settings(s);
  c.width = std::max(1, (s.width + 3) / 4);
  c.height = std::max(1, (s.height + 3) / 4);
  c.path.samples_per_pixel = 1;
  c.path.noise_threshold = 0.0f;
  return c;
}

}  // namespace

PreviewRenderer::PreviewRenderer(PreviewBoard& board) : board_(board), thread_([this] { run(); }) {}

PreviewRenderer::~PreviewRenderer() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void PreviewRenderer::start(Job job) {
  {
    const std::lock_guard lock(mutex_);
    current_ = job;
    pending_ = std::move(job);
    cancel_ = true;  // the render in progress stops before its next pixel
  }
  wake_.notify_all();
}

void PreviewRenderer::show(std::shared_ptr<const LoadedScene> scene, const RenderSettings& settings, uint64_t version,
                           int frame, Clock::time_point seen) {
  Job job{std::move(scene), settings, version, frame, seen};
  {
    const std::lock_guard lock(mutex_);
    if (current_) {
      job.yaw = current_->yaw;
      job.pitch = current_->pitch;
    }
  }
  start(std::move(job));
}

void PreviewRenderer::show_orbit(float yaw, float pitch) {
  std::optional<Job> job;
  {
    const std::lock_guard lock(mutex_);
    job = current_;
  }
  if (!job) return;
  job->yaw = yaw;
  job->pitch = pitch;
  job->seen = Clock::now();
  start(std::move(*job));
}

void PreviewRenderer::show_frame(int frame) {
  std::optional<Job> job;
  {
    const std::lock_guard lock(mutex_);
    job = current_;
  }
  if (!job) return;
  job->frame = frame;
  job->seen = Clock::now();
  start(std::move(*job));
}

int PreviewRenderer::frame() const {
  const std::lock_guard lock(mutex_);
  return current_ ? current_->frame : 0;
}

void PreviewRenderer::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || pending_.has_value(); });
      if (stopping_) return;
      job = std::move(*pending_);
      pending_.reset();
      cancel_ = false;
    }
    try {
      render_job(job);
    } catch (const std::exception& e) {
      Diagnostic d;
      d.file = board_.status().scene;
      d.message = std::string("the preview render failed: ") + e.what();
      board_.post_failure({d});
    }
    board_.post_progress(0.0, false);
  }
}

void PreviewRenderer::render_job(const Job& job) {
  const LoadedScene& loaded = *job.scene;
  const RenderSettings& settings = job.settings;
  const bool path_traced = integrator_samples_pixels(settings.integrator);
  const bool radiance = integrator_shows_radiance(settings.integrator);
  FrameScenes frames(loaded.graph, loaded.frame, loaded.scene,
                     BvhBuildOptions{resolve_thread_count(settings.threads), loaded.scene.bvh.isa()});
  const Scene& scene = frames.at(job.frame);
  const auto since_seen = [&] {
    return std::chrono::duration<double>(PreviewRenderer::Clock::now() - job.seen).count();
  };
  uint64_t rays = 0;  // of the stages before this one

  RenderView view;
  view.aovs = true;
  const Camera orbited = orbit(scene.camera, job.yaw, job.pitch);
  if (job.yaw != 0.0f || job.pitch != 0.0f) view.camera = &orbited;
  const auto post = [&](const Film& film, const RenderSettings& s, const char* stage, int samples, bool last,
                        uint64_t stage_rays) {
    auto image = std::make_shared<PreviewImage>();
    image->film = film;
    image->scene_version = job.version;
    image->width = settings.width;
    image->height = settings.height;
    image->frame = job.frame;
    image->samples = samples;
    image->target_samples = path_traced ? s.path.samples_per_pixel : 0;
    image->stage = stage;
    image->last = last;
    image->seconds = since_seen();
    image->rays = rays + stage_rays;
    image->radiance = radiance;
    image->path_traced = path_traced;
    image->display = settings.display;
    image->yaw = job.yaw;
    image->pitch = job.pitch;
    board_.post_image(std::move(image));
  };
  // Renders one stage; false when it was dropped for newer work.
  const auto stage = [&](const RenderSettings& s, const char* name, bool last) {
    RenderControl control;
    control.cancel = &cancel_;
    const auto started = PreviewRenderer::Clock::now();
    uint64_t stage_rays = 0;  // so far, as the last progress report said
    control.progress = [&](const RenderProgress& p) {
      stage_rays = p.rays;
      const double t = std::chrono::duration<double>(PreviewRenderer::Clock::now() - started).count();
      board_.post_progress(t > 0.0 ? static_cast<double>(p.rays) / t : 0.0, true);
    };
    if (path_traced && last)
      control.pass_done = [&](const Film& film, int samples) { post(film, s, "pass", samples, false, stage_rays); };
    Film film;
    const RenderStats stats = render(scene, s, film, control, static_cast<uint32_t>(job.frame), view);
    if (stats.cancelled) return false;
    const int samples = path_traced ? s.path.samples_per_pixel
                                    : static_cast<int>(std::min<uint64_t>(
                                          max_camera_rays_per_frame(s) / std::max<uint64_t>(1, pixel_count(s)), 65535));
    post(film, s, name, samples, last, stats.rays.total());
    rays += stats.rays.total();
    return true;
  };

  if (!stage(coarse_settings(settings, path_traced), "coarse", false)) return;
  if (path_traced) {
    // One sample a pixel over the whole image first: a pass of 8 takes 8 times as long.
    RenderSettings draft = settings;
    draft.path.samples_per_pixel = 1;
    draft.path.noise_threshold = 0.0f;
    if (settings.path.samples_per_pixel > 1 && !stage(draft, "draft", false)) return;
    stage(settings, "pass", true);
    return;
  }
  const RenderSettings draft = preview_settings(settings);
  const bool same = draft.antialias.mode == settings.antialias.mode &&
                    draft.shadow_samples == settings.shadow_samples && draft.glossy_samples == settings.glossy_samples;
  if (!stage(draft, same ? "final" : "draft", same)) return;
  if (!same) stage(settings, "final", true);
}

}  // namespace rt
