#include "cli/render/settings_text.h"

#include "cli/frames/render_metadata.h"

namespace rt {

std::string settings_text(const RenderSettings& s, const PixelChoices& c, StereoMode stereo) {
  const AntialiasSettings& aa = s.antialias;
  std::string t;
  const auto add = [&](const std::string& key, const std::string& value) { t += key + "=" + value + ";"; };
  add("size", std::to_string(s.width) + "x" + std::to_string(s.height));
  add("seed", std::to_string(s.seed));
  if (s.sampler != SampleSequence::kSobol) add("sampler", std::string(kSampleSequences.name(s.sampler)));
  add("integrator", s.integrator);
  add("max_depth", std::to_string(s.max_depth));
  add("antialias", aa.mode + "," + std::to_string(aa.samples) + "," + (aa.jitter ? "jitter" : "grid") + "," +
                       float_text(aa.threshold) + "," + std::to_string(aa.max_depth) + "," +
                       std::string(kSamplePositions.name(aa.positions)));
  add("glossy", s.glossy ? std::to_string(s.glossy_samples) : "off");
  add("shadow_samples", std::to_string(s.shadow_samples) + (s.scale_secondary_shadows ? ",scaled" : ",full"));
  add("detail", std::string(s.detail.textures ? "textures" : "no-textures") + "," +
                    (s.detail.bumps ? "bumps" : "no-bumps") + "," +
                    (s.detail.override_filter ? std::to_string(static_cast<int>(s.detail.filter)) : "own"));
  add("display", float_text(s.display.exposure) + "," + std::string(kToneMaps.name(s.display.curve)));
  add("path", std::to_string(s.path.samples_per_pixel) + "," + float_text(s.path.noise_threshold) + "," +
                  float_text(s.path.clamp) + "," + std::to_string(static_cast<int>(s.path.strategy)));
  add("stereo", std::string(kStereoModes.name(stereo)));
  add("camera", c.camera);
  add("background", c.background);
  add("ambient", c.ambient);
  if (!c.environment.empty()) add("environment", c.environment);
  add("animation", c.animation);
  add("fps", c.fps ? float_text(*c.fps) : "");
  return t;
}

}  // namespace rt
