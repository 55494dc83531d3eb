#include "cli/render/settings_overrides.h"

#include "cli/common/number_checks.h"
#include "cli/common/report.h"
#include "cli/common/scene_loading.h"
#include "core/render/integrator.h"

namespace rt {

RenderSettings with_overrides(RenderSettings s, const RenderCommand& cmd) {
  if (cmd.preview) s = preview_settings(s);  // first: an option given beside it still wins
  if (cmd.width) s.width = *cmd.width;
  if (cmd.height) s.height = *cmd.height;
  if (cmd.seed) s.seed = *cmd.seed;
  if (cmd.threads) s.threads = *cmd.threads;
  if (cmd.integrator) s.integrator = *cmd.integrator;
  if (cmd.glossy_samples) s.glossy_samples = *cmd.glossy_samples;
  if (cmd.no_glossy) s.glossy = false;
  if (cmd.no_textures) s.detail.textures = false;
  if (cmd.no_bumps) s.detail.bumps = false;
  if (cmd.texture_filter) {  // the job checked the name
    s.detail.override_filter = true;
    s.detail.filter = *kTextureFilters.parse(*cmd.texture_filter);
  }
  if (cmd.shadow_samples) s.shadow_samples = *cmd.shadow_samples;
  if (cmd.sampler) s.sampler = *kSampleSequences.parse(*cmd.sampler);
  if (cmd.secondary_shadows) s.scale_secondary_shadows = *kSecondaryShadows.parse(*cmd.secondary_shadows);
  if (cmd.exposure) s.display.exposure = *cmd.exposure;
  if (cmd.tone_map) s.display.curve = *kToneMaps.parse(*cmd.tone_map);
  if (cmd.max_depth) s.max_depth = *cmd.max_depth;
  if (cmd.spp) s.path.samples_per_pixel = *cmd.spp;
  if (cmd.noise_threshold) s.path.noise_threshold = *cmd.noise_threshold;
  if (cmd.clamp) s.path.clamp = *cmd.clamp;
  if (cmd.aa_mode) s.antialias.mode = *cmd.aa_mode;
  if (cmd.aa_samples) s.antialias.samples = *cmd.aa_samples;
  if (cmd.aa_threshold) s.antialias.threshold = *cmd.aa_threshold;
  if (cmd.aa_depth) s.antialias.max_depth = *cmd.aa_depth;
  if (cmd.aa_positions) s.antialias.positions = *kSamplePositions.parse(*cmd.aa_positions);
  // A debug view's values are data (a normal, a depth): shown as they are, never tone mapped.
  if (!integrator_shows_radiance(s.integrator)) s.display = DisplayTransform{};
  return s;
}

std::optional<LoadOptions> scene_load_options(const RenderCommand& cmd, Isa isa) {
  if (cmd.environment && cmd.background)
    return fail("--environment and --background both replace the scene's background: give one"), std::nullopt;
  if (!cmd.environment && (cmd.environment_intensity || cmd.environment_rotate))
    return fail(std::string(cmd.environment_intensity ? "--environment-intensity" : "--environment-rotate") +
                " applies to --environment's image: give --environment FILE.hdr|.exr"),
           std::nullopt;
  LoadOptions options = cli_load_options(cmd.threads.value_or(0), cmd.camera, cmd.allow_outside_files, isa);
  options.animation = cmd.animation;
  options.fps = cmd.fps;
  options.integrator = cmd.integrator;
  if (cmd.background) options.background = parse_color(*cmd.background);
  if (cmd.ambient) options.ambient = parse_color(*cmd.ambient);
  if (cmd.environment)
    options.environment = LoadOptions::EnvironmentChoice{*cmd.environment, cmd.environment_intensity.value_or(1.0f),
                                                         cmd.environment_rotate.value_or(0.0f)};
  return options;
}

}  // namespace rt
