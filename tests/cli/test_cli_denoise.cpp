// --denoise as a user runs it: the denoised image where the raw one would be (an EXR keeps the raw
// one as layer "raw"), tiles that carry what the denoiser reads and merge into the whole render's
// denoised image byte for byte, and every option that does not go with it refused with the reason.
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "io/image/exr_file.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

using rt::test::rtcli;

namespace {

const std::string kPath = "render scenes/cornell_box.json --width 64 --height 64 --spp 8 -q";

// One channel of a layer (a file lists a layer's channels alphabetically: B, G, R).
std::vector<float> channel(const rt::ExrLayer& layer, const std::string& name) {
  size_t k = 0;
  while (k < layer.channels.size() && layer.channels[k] != name) ++k;
  REQUIRE(k < layer.channels.size());
  std::vector<float> out;
  for (size_t i = k; i < layer.values.size(); i += layer.channels.size()) out.push_back(layer.values[i]);
  return out;
}

}  // namespace

TEST_CASE("cli: --denoise writes the denoised image, an EXR keeps the raw one", "[cli][denoise]") {
  const std::string dir = rt::test::fresh_folder("denoise-outputs");
  REQUIRE(rtcli(kPath + " -o '" + dir + "/raw.png'").code == 0);
  auto r = rtcli(kPath + " --denoise -o '" + dir + "/clean.png'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK(rt::test::read_file(dir + "/clean.png") != rt::test::read_file(dir + "/raw.png"));
  r = rtcli(kPath + " --denoise --exr-float --aov albedo -o '" + dir + "/clean.exr'");
  REQUIRE(r.code == 0);
  std::string error;
  const auto exr = rt::read_exr(dir + "/clean.exr", 1 << 20, error);
  REQUIRE(exr);
  REQUIRE(exr->layer(""));
  REQUIRE(exr->layer("raw"));
  REQUIRE(exr->layer("albedo"));
  CHECK(channel(*exr->layer(""), "G") != channel(*exr->layer("raw"), "G"));
  // The raw layer is the image a render without --denoise writes.
  REQUIRE(rtcli(kPath + " --exr-float -o '" + dir + "/plain.exr'").code == 0);
  const auto plain = rt::read_exr(dir + "/plain.exr", 1 << 20, error);
  REQUIRE(plain);
  for (const char* c : {"R", "G", "B"}) CHECK(channel(*plain->layer(""), c) == channel(*exr->layer("raw"), c));
}

TEST_CASE("cli: tiles rendered with --denoise merge into the whole render's denoised image", "[cli][denoise][split]") {
  const std::string dir = rt::test::fresh_folder("denoise-tiles");
  REQUIRE(rtcli(kPath + " --denoise -o '" + dir + "/whole.png'").code == 0);
  std::string tiles;
  for (int i = 0; i < 3; ++i) {
    const std::string tile = dir + "/tile" + std::to_string(i) + ".exr";
    const auto r = rtcli(kPath + " --denoise --exr-float --tile " + std::to_string(i) + "/3 -o '" + tile + "'");
    INFO(r.output);
    REQUIRE(r.code == 0);
    tiles += " '" + tile + "'";
  }
  std::string error;
  const auto tile = rt::read_exr(dir + "/tile1.exr", 1 << 20, error);
  REQUIRE(tile);
  for (const char* layer : {"albedo", "normal", "depth", "variance", "emission"}) CHECK(tile->layer(layer));
  CHECK_FALSE(tile->layer("raw"));  // a part is denoised once merged
  auto r = rtcli("merge" + tiles + " --denoise -o '" + dir + "/merged.png'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK(rt::test::read_file(dir + "/merged.png") == rt::test::read_file(dir + "/whole.png"));
  // Merged without --denoise: the raw image.
  REQUIRE(rtcli(kPath + " -o '" + dir + "/raw.png'").code == 0);
  REQUIRE(rtcli("merge" + tiles + " -o '" + dir + "/merged-raw.png'").code == 0);
  CHECK(rt::test::read_file(dir + "/merged-raw.png") == rt::test::read_file(dir + "/raw.png"));
}

TEST_CASE("cli: what does not go with --denoise is refused with the reason", "[cli][denoise]") {
  const std::string dir = rt::test::fresh_folder("denoise-refused");
  auto r = rtcli(kPath + " --denoiser oidn -o '" + dir + "/a.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--denoiser: unknown denoiser \"oidn\"") && Catch::Contains("feature"));
  r = rtcli(kPath + " --denoise --stereo side_by_side -o '" + dir + "/b.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--denoise denoises one view"));
  // Tiles without the denoiser's layers.
  REQUIRE(rtcli(kPath + " --exr-float --tile 0/1 -o '" + dir + "/t.exr'").code == 0);
  r = rtcli("merge '" + dir + "/t.exr' --denoise -o '" + dir + "/m.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("render them with --denoise") && Catch::Contains("nothing written"));
  CHECK_FALSE(std::filesystem::exists(dir + "/m.png"));
  // Whitted estimates no variance: the image is left as rendered, and the user told.
  r = rtcli("render scenes/soft_shadows.json --width 32 --height 18 --denoise -o '" + dir + "/w.png'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("only the path tracer estimates"));
}

TEST_CASE("cli: a farm render with --denoise merges its tiles with --denoise", "[cli][denoise][split]") {
  const std::string dir = rt::test::fresh_folder("denoise-farm");
  auto r = rtcli("farm slurm scenes/cornell_box.json --tasks 2 --spp 4 --denoiser feature --dry-run -q -o '" + dir +
                 "/c.png'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(rt::test::read_file(dir + "/c-farm/render.sbatch"), Catch::Contains("'--denoiser' 'feature'"));
  CHECK_THAT(rt::test::read_file(dir + "/c-farm/finish.sbatch"),
             Catch::Contains("/tile_*.exr --denoiser 'feature' -o '" + dir + "/c.png'"));
}
