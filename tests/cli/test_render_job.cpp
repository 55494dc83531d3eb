// The render request, typed and checked before anything is loaded (cli/render/render_job.h):
// what each option becomes, and the combinations it refuses.
#include <catch2/catch.hpp>

#include "cli/render/render_job.h"

using namespace rt;

namespace {

std::optional<std::string> no_slurm(const std::string&) { return std::nullopt; }

}  // namespace

TEST_CASE("render job: the options read once into types", "[cli][job]") {
  RenderCommand cmd;
  cmd.scene = "scenes/turntable.json";
  cmd.output = "frame_####.exr";
  cmd.frames = "1-9x2";
  cmd.tile = "3/8";
  cmd.chunk = "1/2";
  cmd.aov = "depth,albedo";
  cmd.exr_float = true;
  cmd.stereo = "none";
  cmd.background = "0.5";
  const auto job = make_render_job(cmd, no_slurm);
  REQUIRE(job);
  CHECK(job->frames.frames == std::vector<int>{1, 3, 5, 7, 9});
  CHECK(job->frames_given);
  CHECK(job->kind == OutputKind::kExrSequence);
  REQUIRE(job->tile);
  CHECK(job->tile->index == 3);
  CHECK(job->tile->count == 8);
  CHECK(job->chunk->count == 2);
  CHECK(job->aovs == std::vector<std::string>{"depth", "albedo"});
  CHECK(job->choices.stereo == StereoMode::kNone);
  CHECK(job->choices.background == "0.5");
  CHECK(job->choices.camera.empty());

  RenderCommand still;
  still.scene = "models/knot.glb";
  still.crop = "0,10,64,20";
  const auto plain = make_render_job(still, no_slurm);
  REQUIRE(plain);
  CHECK(plain->output == "knot.png");  // beside the current folder, named after the scene
  CHECK(plain->kind == OutputKind::kPng);
  CHECK_FALSE(plain->frames_given);
  REQUIRE(plain->crop);
  CHECK(plain->crop->y1 == 20);
  std::string error;
  CHECK_FALSE(crop_fits(*plain->crop, 64, 16, error));  // the plan's check, once the size is known
  CHECK_THAT(error, Catch::Contains("0 <= y0 < y1 <= 16"));
}

TEST_CASE("render job: options that do not go together are refused before loading", "[cli][job]") {
  const auto refused = [](void (*set)(RenderCommand&)) {
    RenderCommand cmd;
    cmd.scene = "scenes/default.json";
    set(cmd);
    return !make_render_job(cmd, no_slurm).has_value();
  };
  CHECK(refused([](RenderCommand& c) { c.aov = "albedo"; }));  // PNG output
  CHECK(refused([](RenderCommand& c) { c.output = "x.exr", c.aov = "albedo,albedo"; }));
  CHECK(refused([](RenderCommand& c) { c.chunk = "0/2"; }));      // one file
  CHECK(refused([](RenderCommand& c) { c.tile = "auto"; }));      // no Slurm array
  CHECK(refused([](RenderCommand& c) { c.crop = "5,0,3,10"; }));  // x1 <= x0
  CHECK(refused([](RenderCommand& c) { c.tile = "1/4", c.aa_debug = true; }));
  CHECK(refused([](RenderCommand& c) { c.frames = "1-3", c.output = "x.png"; }));  // 3 frames, one PNG
  CHECK(refused([](RenderCommand& c) { c.integrator = "pathh"; }));
  CHECK(refused([](RenderCommand& c) { c.fps = 30.0f; }));  // not a glTF file
  CHECK_FALSE(refused([](RenderCommand& c) { c.output = "x.exr", c.aov = "normal"; }));
}
