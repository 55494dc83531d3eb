// EXR files as a hostile user makes them (issue 36), read by merge, encode, --skip-existing and
// environment images: each refused by name, quickly and in bounded memory; a chunk table that
// points every entry at one chunk, more values than the pixel limit allows, a named pipe, a band
// count of ten million, thousands of overlapping tiles, metadata that would wrap a GIF's delays.
#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "io/image/exr_file.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;
using rt::test::output_path;
using rt::test::read_file;
using rt::test::rtcli;
using rt::test::Run;

namespace {

// A width x height image of `layers` extra 3-channel layers beside the colour, its window `window`.
rt::ExrImage image_of(int width, int height, int layers, rt::PixelWindow window = {}) {
  rt::ExrImage image;
  image.width = width;
  image.height = height;
  image.window = window.empty() ? rt::PixelWindow::whole(width, height) : window;
  const size_t pixels = static_cast<size_t>(image.window.pixels());
  image.layers.push_back(rt::ExrLayer{"", {"R", "G", "B"}, std::vector<float>(pixels * 3, 0.25f)});
  for (int k = 0; k < layers; ++k)
    image.layers.push_back(
        rt::ExrLayer{"extra" + std::to_string(k), {"R", "G", "B"}, std::vector<float>(pixels * 3, 0.5f)});
  return image;
}

std::string write(const std::string& path, const rt::ExrImage& image) {
  std::string error;
  REQUIRE(rt::write_exr(path, image, false, error));
  return path;
}

// The offset of the header's end (the line-offset table's start): after the last attribute.
size_t offset_table(const std::string& bytes) {
  size_t at = 8;
  while (bytes[at] != 0) {
    at = bytes.find('\0', at) + 1;  // name
    at = bytes.find('\0', at) + 1;  // type
    uint32_t size;
    std::memcpy(&size, bytes.data() + at, 4);
    at += 4 + size;
  }
  return at + 1;
}

}  // namespace

TEST_CASE("EXR: a chunk table that points every entry at one chunk is refused before decoding", "[exr][hostile]") {
  const std::string dir = rt::test::fresh_folder("exr-chunks");
  // 256 rows of ZIP: 16 chunks of 16 lines, each decoded once when the table is honest.
  const std::string path = write(dir + "/tile.exr", image_of(256, 256, 2));
  std::string bytes = read_file(path);
  const size_t table = offset_table(bytes);
  uint64_t first;
  std::memcpy(&first, bytes.data() + table, 8);
  for (size_t k = 1; k < 16; ++k) std::memcpy(&bytes[table + 8 * k], &first, 8);
  std::ofstream(dir + "/one-chunk.exr", std::ios::binary) << bytes;
  std::string error;
  CHECK_FALSE(rt::read_exr(dir + "/one-chunk.exr", 1 << 20, error));
  CHECK_THAT(error, Catch::Contains("one-chunk.exr: not a readable OpenEXR image (") &&
                        Catch::Contains("two chunks hold line 0"));
  // A chunk's line moved off the chunk grid.
  bytes = read_file(path);
  {
    uint64_t third;
    std::memcpy(&third, bytes.data() + table + 16, 8);
    const int32_t line_five = 5;
    std::memcpy(&bytes[third], &line_five, 4);
    std::ofstream(dir + "/off-grid.exr", std::ios::binary) << bytes;
    CHECK_FALSE(rt::read_exr(dir + "/off-grid.exr", 1 << 20, error));
    CHECK_THAT(error, Catch::Contains("chunk 2 names line 5, not the first of a chunk"));
  }
  // A chunk's y rewritten to its neighbour's: two chunks claim the same lines.
  bytes = read_file(path);
  uint64_t second;
  std::memcpy(&second, bytes.data() + table + 8, 8);
  const int32_t line_zero = 0;
  std::memcpy(&bytes[second], &line_zero, 4);
  std::ofstream(dir + "/twice.exr", std::ios::binary) << bytes;
  CHECK_FALSE(rt::read_exr(dir + "/twice.exr", 1 << 20, error));
  CHECK_THAT(error, Catch::Contains("two chunks hold line 0"));
  // A chunk's size past the file's end: cut short.
  bytes = read_file(path);
  bytes.resize(bytes.size() - 10);
  std::ofstream(dir + "/short.exr", std::ios::binary) << bytes;
  CHECK_FALSE(rt::read_exr(dir + "/short.exr", 1 << 20, error));
  CHECK_THAT(error, Catch::Contains("incomplete: chunk 15 ends past the file"));
  // The honest file reads.
  CHECK(rt::read_exr(path, 1 << 20, error));
  // merge and encode say the same, naming the file.
  Run r = rt::test::rtcli_bounded("merge '" + dir + "/one-chunk.exr' -o '" + dir + "/m.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("one-chunk.exr: not a readable OpenEXR image"));
  r = rt::test::rtcli_bounded("encode '" + path + "' '" + dir + "/one-chunk.exr' -o '" + dir + "/m.gif'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("frame 2 of 2, ") && Catch::Contains("one-chunk.exr: not a readable"));
  CHECK_FALSE(fs::exists(dir + "/m.gif"));
}

TEST_CASE("EXR: channels x pixels are bounded by the pixel limit before anything is allocated", "[exr][hostile]") {
  const std::string dir = rt::test::fresh_folder("exr-values");
  std::string error;
  // 3 + 3 x 12 = 39 values a pixel: within the 40 read_exr holds.
  CHECK(rt::read_exr(write(dir + "/thirty-nine.exr", image_of(64, 64, 12)), 64 * 64, error));
  // 42 a pixel at the limit's pixels: refused, with the product named.
  CHECK_FALSE(rt::read_exr(write(dir + "/forty-two.exr", image_of(64, 64, 13)), 64 * 64, error));
  CHECK_THAT(error, Catch::Contains("42 channels of 4096 pixels: 172032 values, more than the 163840 read at most"));
  // Under a larger limit the same file reads.
  CHECK(rt::read_exr(dir + "/forty-two.exr", 64 * 64 * 2, error));
}

TEST_CASE("EXR: a named pipe as a tile or a frame is refused, not read forever", "[exr][hostile][cli]") {
  const std::string dir = rt::test::fresh_folder("exr-fifo");
  REQUIRE(::mkfifo((dir + "/tile.exr").c_str(), 0600) == 0);
  Run r = rt::test::rtcli_bounded("merge '" + dir + "/tile.exr' -o '" + dir + "/m.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("tile.exr: is a named pipe (FIFO), not a regular file"));
  r = rt::test::rtcli_bounded("encode '" + dir + "/tile.exr' -o '" + dir + "/m.gif'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("frame 1 of 1, ") && Catch::Contains("named pipe"));
  REQUIRE(::mkfifo((dir + "/frame.png").c_str(), 0600) == 0);
  r = rt::test::rtcli_bounded("encode '" + dir + "/frame.png' -o '" + dir + "/m.gif'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("frame 1 of 1, ") && Catch::Contains("frame.png") && Catch::Contains("named pipe"));
  // A missing frame among others is named by its place.
  r = rt::test::rtcli_bounded("encode '" + write(dir + "/a.exr", image_of(8, 8, 0)) + "' '" + dir + "/gone.exr' -o '" +
                              dir + "/m.gif'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("frame 2 of 2, ") && Catch::Contains("gone.exr"));
}

TEST_CASE("merge: a tile's band count is bounded, and long lists of problems are cut short", "[exr][hostile][cli]") {
  const std::string dir = rt::test::fresh_folder("merge-bands");
  // One band of a 16-row image claiming to be band 0 of ten million, then of two billion.
  for (const char* band : {"0/10000000", "0/2000000000", "0/16"}) {
    INFO(band);
    rt::ExrImage tile = image_of(8, 16, 0, rt::PixelWindow{0, 0, 8, 1});
    tile.attributes["rtcli:tile"] = band;
    write(dir + "/t.exr", tile);
    const Run r = rt::test::rtcli_bounded("merge '" + dir + "/t.exr' -o '" + dir + "/m.png'");
    CHECK(r.code == 2);
    CHECK(r.output.size() < 2000);  // ten million "missing" lines before
    if (std::string(band) == "0/16")
      CHECK_THAT(r.output, Catch::Contains("tile 1/16 is missing") && Catch::Contains("tile 10/16 is missing") &&
                               Catch::Contains("... and 5 more tiles of 16 are missing (15 in all)"));
    else CHECK_THAT(r.output, Catch::Contains("no tile holds pixel (0, 1)"));
  }
  // 300 copies of row 0 of a 300-row image: every pair overlaps (44,850 pairs, each a line before);
  // the first few are named and the rest counted.
  std::string args;
  const std::string row = write(dir + "/row.exr", image_of(8, 300, 0, rt::PixelWindow{0, 0, 8, 1}));
  for (int k = 0; k < 300; ++k) {
    const std::string link = dir + "/r" + std::to_string(k) + ".exr";
    fs::create_symlink(row, link);
    args += " '" + link + "'";
  }
  Run r = rt::test::rtcli_bounded("merge" + args + " -o '" + dir + "/m.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("r0.exr (x 0-7, y 0-0) and") &&
                           Catch::Contains("... and 44840 more overlapping pairs among the 300 tiles read"));
  CHECK(r.output.size() < 8000);
  // Whole-image tiles: reading stops once the tiles hold more than the image's pixels.
  args.clear();
  const std::string whole = write(dir + "/whole.exr", image_of(8, 8, 0));
  for (int k = 0; k < 300; ++k) {
    const std::string link = dir + "/w" + std::to_string(k) + ".exr";
    fs::create_symlink(whole, link);
    args += " '" + link + "'";
  }
  r = rt::test::rtcli_bounded("merge" + args + " -o '" + dir + "/m.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("w0.exr (x 0-7, y 0-7) and") &&
                           Catch::Contains("the first 2 of the 300 tiles already hold more pixels than the image"));
  CHECK(r.output.size() < 4000);
  // A tile without R, G, B is named itself, not the output.
  rt::ExrImage grey = image_of(8, 8, 0);
  grey.layers[0].channels = {"Y", "A", "Z"};
  write(dir + "/grey.exr", grey);
  const Run g = rt::test::rtcli_bounded("merge '" + dir + "/grey.exr' -o '" + dir + "/m.png'");
  CHECK(g.code == 2);
  CHECK_THAT(g.output, Catch::Contains("grey.exr: expected the colour channels R, G, B"));
}

TEST_CASE("encode: a frame rate from an EXR's metadata is checked, and a GIF's delays never wrap",
          "[exr][hostile][cli]") {
  const std::string dir = rt::test::fresh_folder("encode-fps");
  for (const char* fps : {"1e-30", "inf", "nan", "0.001", "fast"}) {
    INFO(fps);
    rt::ExrImage frame = image_of(8, 8, 0);
    frame.attributes["rtcli:fps"] = fps;
    write(dir + "/f.exr", frame);
    const Run r = rt::test::rtcli_bounded("encode '" + dir + "/f.exr' -o '" + dir + "/m.gif'");
    CHECK(r.code == 2);
    CHECK_THAT(r.output,
               Catch::Contains("f.exr: rtcli:fps \"" + std::string(fps) + "\": expected a frame rate from 0.002"));
    CHECK_FALSE(fs::exists(dir + "/m.gif"));
  }
  Run r = rt::test::rtcli_bounded("encode '" + dir + "/f.exr' --fps 0.001 -o '" + dir + "/m.gif'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--fps: expected a number from 0.002 to 1000"));
  // The slowest rate: 500 s a frame, 50000 hundredths (0.001 fps wrapped to 344.6 s before).
  r = rt::test::rtcli_bounded("encode '" + dir + "/f.exr' --fps 0.002 -q -o '" + dir + "/slow.gif'");
  REQUIRE(r.code == 0);
  const std::string gif = read_file(dir + "/slow.gif");
  const size_t gce = gif.find("\x21\xf9\x04");
  REQUIRE(gce != std::string::npos);
  CHECK((static_cast<unsigned char>(gif[gce + 4]) | static_cast<unsigned char>(gif[gce + 5]) << 8) == 50000);
  // A scene whose fps is below a GIF's slowest, rendered to a GIF: refused, naming the rate.
  const std::string scene = rt::test::write_file("encode-fps/slow.json", R"({
    "render": {"width": 8, "height": 8},
    "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
    "lights": [{"type": "point", "position": [0, 4, 4]}],
    "materials": {"m": {"kd": 0.5}},
    "nodes": [{"name": "s", "shape": "sphere", "material": "m"}],
    "animation": {"fps": 0.001, "frames": [0, 1], "tracks": [{"node": "s", "property": "rotate",
      "keys": [{"frame": 0, "value": {"axis": [0, 1, 0], "degrees": 0}}, {"frame": 1, "value": {"axis": [0, 1, 0], "degrees": 90}}]}]}})");
  r = rt::test::rtcli_bounded("render '" + scene + "' -o '" + dir + "/slow-scene.gif'");
  INFO(r.output);
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("0.001 frames per second: a GIF frame lasts at most 655.35 s"));
}

TEST_CASE("cli: --skip-existing renders again an EXR of other settings or with damaged pixels", "[exr][cli][split]") {
  const std::string dir = rt::test::fresh_folder("skip-exr");
  const std::string render = "render scenes/turntable.json --frames 0-1 --width 16 --height 12 --exr-float -o '" + dir +
                             "/f_##.exr' --skip-existing";
  Run r = rtcli(render);
  REQUIRE(r.code == 0);
  r = rtcli(render);
  CHECK_THAT(r.output, Catch::Contains("2 of 2 frames' outputs are already there and complete"));
  // Other settings: both frames again.
  r = rtcli(render + " --seed 7");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, !Catch::Contains("already there"));
  // Another precision or other layers: again.
  r = rtcli("render scenes/turntable.json --frames 0-1 --width 16 --height 12 -o '" + dir +
            "/f_##.exr' --skip-existing --seed 7");
  CHECK_THAT(r.output, !Catch::Contains("already there"));
  // Damaged pixel data behind an intact chunk table: that frame again, the other kept.
  r = rtcli(render);
  CHECK(r.code == 0);
  r = rtcli(render);
  REQUIRE_THAT(r.output, Catch::Contains("2 of 2 frames'"));
  std::string bytes = read_file(dir + "/f_01.exr");
  for (size_t k = bytes.size() - 40; k < bytes.size(); ++k) bytes[k] = static_cast<char>(bytes[k] ^ 0x5a);
  std::ofstream(dir + "/f_01.exr", std::ios::binary) << bytes;
  r = rtcli(render);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("1 of 2 frame's output is already there and complete") &&
                           Catch::Contains("wrote " + dir + "/f_01.exr"));
}

TEST_CASE("an environment image is one of the scene's inputs: never overwritten, and in the scene hash",
          "[exr][cli][hostile]") {
  const std::string dir = rt::test::fresh_folder("env-input");
  fs::copy_file(rt::test::source_path("scenes/textures/sky.hdr"), dir + "/sky.hdr");
  write(dir + "/sky.exr", image_of(16, 8, 0));
  for (const char* sky : {"sky.hdr", "sky.exr"}) {
    rt::test::write_file("env-input/scene.json", std::string(R"({"render": {"width": 16, "height": 8},
      "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0]}, "background": {"environment": ")") +
                                                     sky + R"("},
      "materials": {"m": {"kd": 0.5}}, "lights": [{"type": "point", "position": [0, 3, 0]}],
      "nodes": [{"shape": "sphere", "material": "m"}]})");
    INFO(sky);
    // -o naming the environment image: refused, the image untouched.
    Run r;
    if (std::string(sky) == "sky.exr") {
      const std::string before = read_file(dir + "/sky.exr");
      r = rtcli("render '" + dir + "/scene.json' -o '" + dir + "/sky.exr'");
      CHECK(r.code == 2);
      CHECK_THAT(r.output, Catch::Contains("it is the input file"));
      CHECK(read_file(dir + "/sky.exr") == before);
    }
    // Tiles rendered before and after the image changed do not merge.
    r = rtcli("render '" + dir + "/scene.json' -q --tile 0/2 -o '" + dir + "/t0.exr'");
    REQUIRE(r.code == 0);
    std::ofstream(dir + "/" + sky, std::ios::binary | std::ios::app) << '\n';
    r = rtcli("render '" + dir + "/scene.json' -q --tile 1/2 -o '" + dir + "/t1.exr'");
    REQUIRE(r.code == 0);
    r = rtcli("merge '" + dir + "/t0.exr' '" + dir + "/t1.exr' -o '" + dir + "/m.png'");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("a different scene_hash"));
  }
}
