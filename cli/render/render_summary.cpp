#include "cli/render/render_summary.h"

#include <algorithm>
#include <cstdio>

#include "cli/common/progress_bar.h"
#include "core/render/integrator.h"

namespace rt {

void print_summary(const RenderJob& job, const RenderSettings& settings, const FrameList& frames, const RenderTotals& t,
                   double load_seconds, const std::vector<std::string>& written, Isa isa_used) {
  const char* isa = isa_name(isa_used);  // whose BVH kernels traced the rays
  const double rate = t.seconds > 0 ? static_cast<double>(t.rays.total()) / t.seconds : 0.0;
  const unsigned threads = t.last.threads;
  if (frames.count() == 1) {
    std::fprintf(stderr, "rendered %s: %dx%d in %.2f s (load %.2f s), %srays (%s), %.2f Mrays/s, %u thread%s, %s\n",
                 job.scene.c_str(), settings.width, settings.height, t.seconds, load_seconds,
                 format_count(static_cast<double>(t.rays.total())).c_str(), format_ray_counts(t.rays).c_str(),
                 rate / 1e6, threads, threads == 1 ? "" : "s", isa);
  } else {
    std::fprintf(stderr,
                 "rendered %s: frames %s (%d), %dx%d, %.2f s per frame (placing %.1f ms), %.2f s in all "
                 "(load %.2f s), %srays, %.2f Mrays/s, %u thread%s, %s\n",
                 job.scene.c_str(), frames.text().c_str(), frames.count(), settings.width, settings.height,
                 t.seconds / frames.count(), 1e3 * t.place_seconds / frames.count(), t.seconds + t.place_seconds,
                 load_seconds, format_count(static_cast<double>(t.rays.total())).c_str(), rate / 1e6, threads,
                 threads == 1 ? "" : "s", isa);
  }
  const double pixels = static_cast<double>(t.pixels_per_pass) * frames.count() * t.passes;
  if (!integrator_samples_pixels(settings.integrator)) {
    std::fprintf(stderr, "  %.2f rays per pixel (%.2f camera rays), %.1f%% of pixels refined (anti-aliasing %s)\n",
                 static_cast<double>(t.rays.total()) / pixels, static_cast<double>(t.rays[RayKind::kCamera]) / pixels,
                 100.0 * static_cast<double>(t.refined) / pixels, settings.antialias.mode.c_str());
  } else {
    const double samples = static_cast<double>(t.samples);
    const double traced = static_cast<double>(t.samples - std::min(t.resumed_samples, t.samples));  // here
    std::fprintf(stderr,
                 "  path tracing: %.2f rays per pixel, %.1f samples per pixel (at most %d%s), %.3f Msamples/s, %.2f "
                 "rays per sample\n",
                 static_cast<double>(t.rays.total()) / pixels, samples / pixels, settings.path.samples_per_pixel,
                 settings.path.noise_threshold > 0.0f ? ", adaptive" : "",
                 t.seconds > 0 ? traced / t.seconds / 1e6 : 0.0,
                 traced > 0 ? static_cast<double>(t.rays.total()) / traced : 0.0);
    if (!job.resume.empty())
      std::fprintf(stderr, "  --resume %s: %.1f samples per pixel were there, %.1f added\n", job.resume.c_str(),
                   static_cast<double>(t.resumed_samples) / pixels, traced / pixels);
    if (job.time_limit > 0.0)
      std::fprintf(stderr, "  --time %g s: %s after %d pass%s of %d samples: %.0f samples per pixel%s\n",
                   job.time_limit, t.time_limited ? "stopped" : "finished", t.time_passes,
                   t.time_passes == 1 ? "" : "es", kPassSamples, samples / pixels,
                   t.time_limited ? "" : " (all it asks for, within the time)");
    if (t.rays.invalid_samples > 0)
      std::fprintf(stderr, "rtcli: warning: %llu samples were not a finite, non-negative colour and were dropped\n",
                   static_cast<unsigned long long>(t.rays.invalid_samples));
  }
  if (t.passes == 2) std::fprintf(stderr, "  stereo: each eye rendered at %dx%d\n", settings.width, settings.height);
  if (written.size() <= 3) {
    for (const std::string& w : written) std::printf("wrote %s\n", w.c_str());
  } else {
    std::printf("wrote %s ... %s (%zu files)\n", written.front().c_str(), written.back().c_str(), written.size());
  }
}

}  // namespace rt
