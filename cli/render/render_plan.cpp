#include "cli/render/render_plan.h"

#include <cstdio>

#include "cli/render/aov_layers.h"
#include "cli/frames/render_metadata.h"
#include "cli/render/settings_text.h"
#include "cli/frames/render_share.h"
#include "core/render/band_split.h"

namespace rt {
namespace {

bool fail(const std::string& message) {
  std::fprintf(stderr, "rtcli: error: %s\n", message.c_str());
  return false;
}

// "albedo,normal,depth" in any order, each once.
bool parse_aovs(const std::string& text, std::vector<std::string>& out) {
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!find_aov(name))
      return fail("--aov: expected layers among albedo, normal, depth (comma-separated), found \"" + name + "\"");
    for (const std::string& seen : out)
      if (seen == name) return fail("--aov: \"" + name + "\" is given twice");
    out.push_back(name);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

bool check_combinations(const RenderCommand& cmd, OutputKind kind, const StereoSettings& stereo) {
  if ((cmd.exr_float || cmd.aov) && !is_exr(kind))
    return fail(std::string(cmd.aov ? "--aov" : "--exr-float") + " applies to EXR output (-o NAME.exr or NAME_####.exr)");
  if (stereo.enabled() && (is_exr(kind) || cmd.crop || cmd.tile))
    return fail(std::string(is_exr(kind) ? "EXR output" : cmd.crop ? "--crop" : "--tile") +
                " renders one view; it does not go with a stereo camera (--stereo none renders the left eye's view)");
  if (cmd.chunk && !is_sequence(kind))
    return fail("--chunk renders a share of the frames: write them as numbered files (-o NAME_####.png or "
                "NAME_####.exr), then join them with rtcli encode");
  if ((cmd.crop || cmd.tile) && (cmd.aa_debug || cmd.samples_debug))
    return fail(std::string(cmd.aa_debug ? "--aa-debug" : "--samples-debug") + " shows the whole image; it does not go with " +
                (cmd.crop ? "--crop" : "--tile"));
  return true;
}

}  // namespace

std::optional<RenderPlan> plan_render(const RenderCommand& cmd, OutputKind kind, const std::vector<std::string>& patterns,
                                      const FrameList& frames, const RenderSettings& settings,
                                      const StereoSettings& stereo, const LoadedScene& loaded) {
  if (!check_combinations(cmd, kind, stereo)) return std::nullopt;
  RenderPlan plan;
  plan.frames = frames;
  std::string error;
  const EnvironmentLookup env = process_environment();
  if (cmd.crop) {
    const auto w = parse_crop(*cmd.crop, settings.width, settings.height, error);
    if (!w) return fail(error), std::nullopt;
    plan.content.window = *w;
  }
  if (cmd.tile) {
    const auto share = parse_share(*cmd.tile, "--tile", env, error);
    if (!share) return fail(error), std::nullopt;
    if (share->count > settings.height)
      return fail("--tile " + *cmd.tile + ": " + std::to_string(share->count) + " bands of rows for an image " +
                  std::to_string(settings.height) + " rows high; give at most one band a row"),
             std::nullopt;
    plan.content.window = cost_balanced_bands(loaded.scene, settings, share->count,
                                              static_cast<uint32_t>(loaded.frame))[static_cast<size_t>(share->index)];
    plan.content.identity.tile = share_text(*share);
  }
  if (cmd.chunk) {
    const auto share = parse_share(*cmd.chunk, "--chunk", env, error);
    if (!share) return fail(error), std::nullopt;
    plan.frames = frames.chunk(share->index, share->count);
    if (plan.frames.frames.empty())
      plan.skipped = "chunk " + std::to_string(share->index) + "/" + std::to_string(share->count) + " of " +
                     std::to_string(frames.count()) + " frames has none to render";
  }
  if (cmd.aov && !parse_aovs(*cmd.aov, plan.content.aovs)) return std::nullopt;
  plan.content.exr_float = cmd.exr_float;
  if (is_exr(kind)) {
    RenderIdentity& id = plan.content.identity;
    id.scene = cmd.scene;
    id.scene_hash = hash_files(loaded.inputs);
    id.settings = settings_text(settings, cmd, stereo.mode);
    id.seed = settings.seed;
    id.display = settings.display;
    id.fps = loaded.graph.timeline.fps;
  }
  if (cmd.skip_existing) {
    FrameList left;
    ExpectedExr expected;
    expected.layers = plan.content.aovs;
    expected.full_float = plan.content.exr_float;
    const PixelWindow window =
        plan.content.window.empty() ? PixelWindow{0, 0, settings.width, settings.height} : plan.content.window;
    for (const int f : plan.frames.frames) {
      bool done = true;
      if (is_exr(kind)) expected.attributes = render_attributes(plan.content.identity, f, window);
      for (const std::string& pattern : patterns)
        done = done && output_is_complete(is_sequence(kind) ? sequence_path(pattern, f) : pattern, kind, expected);
      if (!done) left.frames.push_back(f);
    }
    const int skipped = plan.frames.count() - left.count();
    if (skipped > 0)
      plan.skipped = std::to_string(skipped) + " of " + std::to_string(plan.frames.count()) +
                     (skipped == 1 ? " frame's" : " frames'") + " output" + (skipped == 1 ? " is" : "s are") +
                     " already there and complete (--skip-existing)";
    plan.frames = left;
  }
  return plan;
}

}  // namespace rt
