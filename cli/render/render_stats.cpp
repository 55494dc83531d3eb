#include "cli/render/render_stats.h"

#include "core/render/integrator.h"
#include "io/base/atomic_file.h"
#include "io/json/document.h"

namespace rt {

std::string render_stats_json(const RenderStatsInput& in) {
  const RenderTotals& t = in.totals;
  const double pixels = static_cast<double>(t.pixels_per_pass) * in.frames.count() * t.passes;
  Json rays = Json::object();
  for (size_t k = 0; k < kRayKindCount; ++k) rays[kRayKindNames[k]] = t.rays.count[k];
  rays["total"] = t.rays.total();
  Json out = {
      {"rtcli", RTCLI_VERSION},
      {"scene", in.scene},
      {"outputs", in.outputs},
      {"width", in.settings.width},
      {"height", in.settings.height},
      {"frames", {in.frames.first(), in.frames.last()}},
      {"frame_list", in.frames.text()},
      {"stereo", std::string(kStereoModes.name(in.stereo.mode))},
      {"eyes", t.passes},
      {"threads", t.last.threads},
      {"isa", isa_name(in.isa)},
      {"seed", in.settings.seed},
      {"sampler", std::string(kSampleSequences.name(in.settings.sampler))},
      {"integrator", in.settings.integrator},
      {"antialias", in.settings.antialias.mode},
      {"shadow_samples", in.settings.shadow_samples},
      {"secondary_shadows", std::string(kSecondaryShadows.name(in.settings.scale_secondary_shadows))},
      {"glossy_samples", in.settings.glossy ? in.settings.glossy_samples : 0},
      {"max_depth", in.settings.max_depth},
      {"exposure", in.settings.display.exposure},
      {"tone_map", std::string(kToneMaps.name(in.settings.display.curve))},
      {"seconds", {{"render", t.seconds}, {"placing", t.place_seconds}, {"load", in.load_seconds}}},
      {"rays", rays},
      {"rays_per_pixel", pixels > 0 ? static_cast<double>(t.rays.total()) / pixels : 0.0},
      {"camera_rays_per_pixel", pixels > 0 ? static_cast<double>(t.rays.count[0]) / pixels : 0.0},
      {"refined_pixels", pixels > 0 ? static_cast<double>(t.refined) / pixels : 0.0},
      {"mrays_per_second", t.seconds > 0 ? static_cast<double>(t.rays.total()) / t.seconds / 1e6 : 0.0},
  };
  if (integrator_samples_pixels(in.settings.integrator)) {
    const double samples = static_cast<double>(t.samples);
    out["path"] = {
        {"samples_per_pixel", in.settings.path.samples_per_pixel},
        {"noise_threshold", in.settings.path.noise_threshold},
        {"clamp", in.settings.path.clamp},
        {"mean_samples_per_pixel", pixels > 0 ? samples / pixels : 0.0},
        {"msamples_per_second", t.seconds > 0 ? samples / t.seconds / 1e6 : 0.0},
        {"invalid_samples", t.rays.invalid_samples},
    };
    if (in.time_limit > 0.0)
      out["path"]["time"] = {{"limit", in.time_limit}, {"passes", t.time_passes}, {"stopped", t.time_limited}};
  }
  return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

bool write_render_stats(const std::string& path, const RenderStatsInput& in, std::string& error) {
  const std::string text = render_stats_json(in);
  return write_file_atomically(path, std::vector<uint8_t>(text.begin(), text.end()), error);
}

}  // namespace rt
