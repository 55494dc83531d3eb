#include "cli/render/render_job.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/common/report.h"
#include "cli/common/suggestions.h"
#include "cli/frames/output_checks.h"
#include "cli/render/aov_layers.h"
#include "core/denoise/denoiser.h"
#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

std::string default_output(const std::string& scene, bool animation) {
  return std::filesystem::path(scene).stem().string() + (animation ? ".gif" : ".png");
}

// A name one of the name tables must hold, or an error listing the names it holds.
template <class T>
bool check_name(const char* option, const char* what, const std::optional<std::string>& name,
                const NameTable<T>& table) {
  if (!name || table.find(*name)) return true;
  std::fprintf(stderr, "rtcli: error: %s: unknown %s \"%s\"%s; expected one of: %s\n", option, what, name->c_str(),
               did_you_mean(*name, table.names()).c_str(), table.list().c_str());
  return false;
}

bool check_names(const RenderCommand& cmd) {
  return check_name("--integrator", "integrator", cmd.integrator, integrators()) &&
         check_name("--aa", "anti-aliasing mode", cmd.aa_mode, pixel_samplers()) &&
         check_name("--texture-filter", "texture filter", cmd.texture_filter, kTextureFilters) &&
         check_name("--secondary-shadows", "secondary shadow rule", cmd.secondary_shadows, kSecondaryShadows) &&
         check_name("--sampler", "sampler", cmd.sampler, kSampleSequences) &&
         check_name("--tone-map", "tone curve", cmd.tone_map, kToneMaps) &&
         check_name("--aa-positions", "sample position", cmd.aa_positions, kSamplePositions) &&
         check_name("--stereo", "stereo mode", cmd.stereo, kStereoModes) &&
         check_name("--denoiser", "denoiser", cmd.denoiser, denoisers()) &&
         check_name("--progress", "progress style", cmd.progress, kProgressStyles);
}

// "albedo,normal,depth" in any order, each once.
bool parse_aovs(const std::string& text, std::vector<std::string>& out) {
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!find_aov(name))
      return fail("--aov: expected layers among albedo, normal, depth, variance (comma-separated), found \"" + name +
                  "\"");
    for (const std::string& seen : out)
      if (seen == name) return fail("--aov: \"" + name + "\" is given twice");
    out.push_back(name);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

// The frames the command asks for; without --frame or --frames, the scene's first frame.
std::optional<FrameList> requested_frames(const RenderCommand& cmd) {
  if (!cmd.frames) return FrameList::range(0, 0);
  std::string error;
  const auto list = parse_frame_list(*cmd.frames, error);
  if (!list)
    std::fprintf(stderr,
                 "rtcli: error: --frames: %s; expected a frame N, a range A-B, every S-th frame A-BxS, or a list "
                 "of those (1,5,9-12), whole numbers within +-%d\n",
                 error.c_str(), kMaxFrameNumber);
  return list;
}

// The output and its kind, and what may be written beside it.
bool read_output(const RenderCommand& cmd, RenderJob& job) {
  job.output = cmd.output.empty() ? default_output(cmd.scene, job.frames.count() > 1) : cmd.output;
  std::string error;
  const std::optional<OutputKind> kind = output_kind(job.output, error);
  if (!kind || !check_output(job.output, error)) return fail(error);
  job.kind = *kind;
  if (job.frames.count() > 1 && is_single_image(job.kind))
    return fail(std::to_string(job.frames.count()) +
                " frames need an animated GIF (-o NAME.gif) or numbered files (-o NAME_####.png or NAME_####.exr), "
                "found \"" +
                job.output + "\"");
  const bool stereo = job.choices.stereo && *job.choices.stereo != StereoMode::kNone;
  if (job.aa_debug && stereo) return fail("--aa-debug shows one image's refinement; it does not go with --stereo");
  if (job.samples_debug && (stereo || job.kind != OutputKind::kPng))
    return fail("--samples-debug writes one image beside one PNG (no --stereo, no \"" + job.output + "\")");
  if (job.aa_debug && job.kind != OutputKind::kPng)
    return fail("--aa-debug writes images beside one PNG; it does not go with \"" + job.output + "\"");
  if ((job.exr_float || !job.aovs.empty()) && !is_exr(job.kind))
    return fail(std::string(job.aovs.empty() ? "--exr-float" : "--aov") +
                " applies to EXR output (-o NAME.exr or NAME_####.exr)");
  if (!job.denoiser.empty() && stereo)
    return fail("--denoise denoises one view; it does not go with --stereo (--stereo none renders the left eye's)");
  if (job.chunk && !is_sequence(job.kind))
    return fail(
        "--chunk renders a share of the frames: write them as numbered files (-o NAME_####.png or "
        "NAME_####.exr), then join them with rtcli encode");
  if (!job.resume.empty() && (stereo || job.chunk || is_sequence(job.kind) || job.kind == OutputKind::kGif))
    return fail("--resume continues one frame's render into one image; it does not go with " +
                std::string(stereo      ? "--stereo"
                            : job.chunk ? "--chunk"
                                        : "\"" + job.output + "\""));
  if ((job.crop || job.tile) && (job.aa_debug || job.samples_debug))
    return fail(std::string(job.aa_debug ? "--aa-debug" : "--samples-debug") +
                " shows the whole image; it does not go with " + (job.crop ? "--crop" : "--tile"));
  return true;
}

// --view-transform, --look, --ocio-config: the OpenColorIO view PNG and GIF frames go through.
bool read_view(const RenderCommand& cmd, RenderJob& job) {
  if (!cmd.view_transform) {
    if (cmd.look || cmd.ocio_config)
      return fail(std::string(cmd.look ? "--look" : "--ocio-config") + " goes with --view-transform NAME");
    return true;
  }
  if (cmd.tone_map)
    return fail("--view-transform replaces the tone curve; it does not go with --tone-map (choose one)");
  const std::string config = cmd.ocio_config.value_or(ViewTransform::blender_config());
  if (config.empty()) {
    // Blender's Standard is the sRGB encoding of the clipped radiance: rtcli's own "clamp".
    if (!cmd.look && (*cmd.view_transform == "standard" || *cmd.view_transform == "Standard")) return true;
    return fail("--view-transform " + *cmd.view_transform +
                " needs an OpenColorIO config: --ocio-config FILE (Blender's is datafiles/colormanagement/"
                "config.ocio; none at " +
                kBlenderConfigs[0] + ")");
  }
  std::string error;
  job.view = ViewTransform::open(config, *cmd.view_transform, cmd.look.value_or(""), error);
  if (!job.view) return fail("--view-transform " + *cmd.view_transform + " (" + config + "): " + error);
  return true;
}

// --crop, --tile and --chunk: the part of the render asked for.
bool read_share(const RenderCommand& cmd, const EnvironmentLookup& env, RenderJob& job) {
  std::string error;
  if (cmd.crop) {
    job.crop = parse_crop_text(*cmd.crop, error);
    if (!job.crop) return fail(error);
  }
  if (cmd.tile) {
    job.tile = parse_share(*cmd.tile, "--tile", env, error);
    if (!job.tile) return fail(error);
  }
  if (cmd.chunk) {
    job.chunk = parse_share(*cmd.chunk, "--chunk", env, error);
    if (!job.chunk) return fail(error);
  }
  return true;
}

}  // namespace

std::optional<RenderJob> make_render_job(const RenderCommand& cmd, const EnvironmentLookup& env) {
  if (!check_names(cmd)) return std::nullopt;
  if ((cmd.fps || cmd.animation) && !is_gltf_path(cmd.scene)) {
    std::fprintf(stderr, "rtcli: error: %s applies to a glTF file rendered on its own; a scene file sets %s\n",
                 cmd.fps ? "--fps" : "--animation",
                 cmd.fps ? "\"animation\": {\"fps\": ...}" : "\"animation\" on its glTF reference (\"mesh\")");
    return std::nullopt;
  }
  RenderJob job;
  job.scene = cmd.scene;
  const std::optional<FrameList> asked = requested_frames(cmd);
  if (!asked) return std::nullopt;
  job.frames = *asked;
  job.frames_given = cmd.frames.has_value();
  job.stats = cmd.stats;
  job.skip_existing = cmd.skip_existing;
  job.time_limit = cmd.time.value_or(0.0);
  job.resume = cmd.resume.value_or("");
  job.exr_float = cmd.exr_float;
  if (cmd.denoise || cmd.denoiser) job.denoiser = cmd.denoiser.value_or(std::string(denoisers().entries()[0].name));
  job.aa_debug = cmd.aa_debug;
  job.samples_debug = cmd.samples_debug;
  job.dither = cmd.dither;
  job.quiet = cmd.quiet;
  if (cmd.progress) job.progress = *kProgressStyles.parse(*cmd.progress);  // checked by check_names
  PixelChoices& c = job.choices;
  c.camera = cmd.camera.value_or("");
  c.background = cmd.background.value_or("");
  c.ambient = cmd.ambient.value_or("");
  if (cmd.environment)
    c.environment = *cmd.environment + "," + std::to_string(cmd.environment_intensity.value_or(1.0f)) + "," +
                    std::to_string(cmd.environment_rotate.value_or(0.0f));
  c.animation = cmd.animation.value_or("");
  c.fps = cmd.fps;
  if (cmd.stereo) c.stereo = kStereoModes.parse(*cmd.stereo);  // checked by check_names
  if (cmd.aov && !parse_aovs(*cmd.aov, job.aovs)) return std::nullopt;
  if (!read_share(cmd, env, job) || !read_output(cmd, job) || !read_view(cmd, job)) return std::nullopt;
  return job;
}

}  // namespace rt
