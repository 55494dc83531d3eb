// render --resume FILE.exr: samples added to an earlier render give the pixels of one render of
// them all, byte for byte (a PNG) and bit for bit (an EXR's colour and sums); parts of an image
// (--tile, merged tiles) continue alike; another render's file is refused, saying what differs.
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "io/image/exr_file.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace {

const std::string kScene = "scenes/cornell_box.json";
const std::string kSmall = " --width 48 --height 36 -q ";

rt::ExrImage read(const std::string& path) {
  std::string error;
  auto image = rt::read_exr(path, 1u << 20, error);
  INFO(error);
  REQUIRE(image);
  return std::move(*image);
}

void check_same_layers(const rt::ExrImage& a, const rt::ExrImage& b) {
  REQUIRE(a.layers.size() == b.layers.size());
  for (size_t i = 0; i < a.layers.size(); ++i) {
    INFO("layer \"" << a.layers[i].name << "\"");
    CHECK(a.layers[i].name == b.layers[i].name);
    CHECK(a.layers[i].values == b.layers[i].values);
  }
}

rt::test::Run render(const std::string& args) { return rt::test::rtcli("render " + kScene + kSmall + args); }

}  // namespace

TEST_CASE("cli: render --resume continues a render to the pixels of one render of all the samples", "[cli][resume]") {
  const std::string out = rt::test::fresh_folder("resume");
  REQUIRE(render("--spp 16 -o " + out + "/a.exr").code == 0);
  REQUIRE(render("--spp 40 -o " + out + "/once.exr").code == 0);
  REQUIRE(render("--spp 40 -o " + out + "/once.png").code == 0);
  const rt::test::Run resumed = render("--resume " + out + "/a.exr --spp 40 -o " + out + "/b.exr");
  INFO(resumed.output);
  REQUIRE(resumed.code == 0);
  REQUIRE(render("--resume " + out + "/a.exr --spp 40 -o " + out + "/b.png").code == 0);
  CHECK(rt::test::read_file(out + "/b.png") == rt::test::read_file(out + "/once.png"));  // byte-identical
  // The summary tells the samples kept from those added.
  const rt::test::Run told = rt::test::rtcli("render " + kScene + " --width 48 --height 36 --resume " + out +
                                             "/a.exr --spp 40 -o " + out + "/told.png");
  CHECK_THAT(told.output, Catch::Contains("40.0 samples per pixel (at most 40)") &&
                              Catch::Contains("/a.exr: 16.0 samples per pixel were there, 24.0 added"));
  const rt::ExrImage once = read(out + "/once.exr"), b = read(out + "/b.exr");
  check_same_layers(once, b);  // the colour and the sums
  CHECK(b.layer("state.count"));
  CHECK(b.layer("state.sum")->exact);  // 32-bit floats in a half-float file
  // And on again from the continued file, in passes (--time), with the first hit's layers and a
  // noise threshold: still the one render's bits.
  const std::string more = " --aov albedo,normal --noise-threshold 0.05 ";
  REQUIRE(render(more + "--spp 16 -o " + out + "/c.exr").code == 0);
  REQUIRE(render(more + "--resume " + out + "/c.exr --spp 32 --time 1000 -o " + out + "/d.exr").code == 0);
  REQUIRE(render(more + "--resume " + out + "/d.exr --spp 48 -o " + out + "/e.exr").code == 0);
  REQUIRE(render(more + "--spp 48 -o " + out + "/once48.exr").code == 0);
  check_same_layers(read(out + "/once48.exr"), read(out + "/e.exr"));
}

TEST_CASE("cli: render --resume refines a tile, and merged tiles as one image", "[cli][resume][farm]") {
  const std::string out = rt::test::fresh_folder("resume-tiles");
  REQUIRE(render("--spp 8 --tile 0/2 -o " + out + "/t0.exr").code == 0);
  REQUIRE(render("--spp 8 --tile 1/2 -o " + out + "/t1.exr").code == 0);
  REQUIRE(render("--tile 0/2 --resume " + out + "/t0.exr --spp 24 -o " + out + "/t0b.exr").code == 0);
  REQUIRE(render("--tile 0/2 --spp 24 -o " + out + "/t0once.exr").code == 0);
  check_same_layers(read(out + "/t0once.exr"), read(out + "/t0b.exr"));
  // A tile is not the whole image: refused by name.
  const rt::test::Run whole = render("--resume " + out + "/t0.exr --spp 24 -o " + out + "/x.exr");
  CHECK(whole.code == 2);
  CHECK_THAT(whole.output, Catch::Contains("the pixels rendered"));
  // Merged tiles keep their sums: the whole image continues.
  REQUIRE(rt::test::rtcli("merge " + out + "/t0.exr " + out + "/t1.exr -o " + out + "/m.exr").code == 0);
  REQUIRE(render("--resume " + out + "/m.exr --spp 24 -o " + out + "/m24.png").code == 0);
  REQUIRE(render("--spp 24 -o " + out + "/once24.png").code == 0);
  CHECK(rt::test::read_file(out + "/m24.png") == rt::test::read_file(out + "/once24.png"));
}

TEST_CASE("cli: render --resume refuses another render's file, naming what differs", "[cli][resume][errors]") {
  const std::string out = rt::test::fresh_folder("resume-refused");
  REQUIRE(render("--spp 16 -o " + out + "/a.exr").code == 0);
  const auto refused = [&](const std::string& args, const std::string& message) {
    const rt::test::Run r = render(args);
    INFO(r.output);
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains(message));
  };
  refused("--resume " + out + "/a.exr --spp 40 --seed 9 -o " + out + "/x.png", "setting seed (1, now 9)");
  refused("--resume " + out + "/a.exr --spp 8 -o " + out + "/x.png", "it has 16 samples a pixel already");
  refused("--resume " + out + "/a.exr --spp 40 --integrator whitted -o " + out + "/x.png",
          "adds samples to the path tracer's render");
  refused("--resume " + out + "/a.exr --spp 40 --aov albedo -o " + out + "/x.exr",
          "was rendered without the first hit's layers");
  refused("--resume " + out + "/a.exr --spp 40 -o " + out + "/x_####.png --frames 0-1",
          "--resume continues one frame's render");
  refused("--resume " + out + "/missing.exr --spp 40 -o " + out + "/x.png", "missing.exr");
  // A changed scene file: the hash of the scene's files differs.
  const std::string scene = out + "/scene.json";
  std::filesystem::copy_file(rt::test::source_path(kScene), scene);
  REQUIRE(rt::test::rtcli("render " + scene + kSmall + "--spp 8 -o " + out + "/s.exr").code == 0);
  std::ofstream(scene, std::ios::app) << "\n";
  const rt::test::Run changed =
      rt::test::rtcli("render " + scene + kSmall + "--resume " + out + "/s.exr --spp 16 -o " + out + "/x.png");
  CHECK(changed.code == 2);
  CHECK_THAT(changed.output, Catch::Contains("another render's: the scene (its files have changed since"));
  // A file whose sums were tampered with (a count beyond any render's): refused, not trusted.
  rt::ExrImage bad = read(out + "/a.exr");
  for (rt::ExrLayer& l : bad.layers)
    if (l.name == "state.count") l.values[5] = 1e9f;
  std::string error;
  REQUIRE(rt::write_exr(out + "/bad.exr", bad, false, error));
  refused("--resume " + out + "/bad.exr --spp 40 -o " + out + "/x.png", "expected a count of 1 to");
  // Half-float sums cannot be continued exactly.
  for (rt::ExrLayer& l : bad.layers) l.exact = false;
  REQUIRE(rt::write_exr(out + "/half.exr", bad, false, error));
  refused("--resume " + out + "/half.exr --spp 40 -o " + out + "/x.png", "as half floats");
}
