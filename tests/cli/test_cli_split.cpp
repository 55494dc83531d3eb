// A render split into parts, as a cluster runs it: tiles (--tile, --crop) in EXR merged by `rtcli
// merge`, frame chunks (--chunk) encoded by `rtcli encode`, resumed with --skip-existing; the
// result byte-identical to the render on one machine, and every problem with the parts named.
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "io/image/exr_file.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

using rt::test::rtcli;

namespace {

const std::string kStill = "render scenes/antialias.json --width 96 --height 54 -q";

}  // namespace

TEST_CASE("cli: 8 EXR tiles merge into the PNG and the EXR a whole render writes, byte for byte", "[cli][split]") {
  const std::string dir = rt::test::fresh_folder("split-tiles");
  REQUIRE(rtcli(kStill + " -o '" + dir + "/whole.png'").code == 0);
  REQUIRE(rtcli(kStill + " --exr-float --aov albedo,normal,depth -o '" + dir + "/whole.exr'").code == 0);
  std::string tiles;
  for (int i = 0; i < 8; ++i) {
    const std::string tile = dir + "/tile" + std::to_string(i) + ".exr";
    const auto r =
        rtcli(kStill + " --exr-float --aov albedo,normal,depth --tile " + std::to_string(i) + "/8 -o '" + tile + "'");
    INFO(r.output);
    REQUIRE(r.code == 0);
    tiles += " '" + tile + "'";
  }
  auto r = rtcli("merge" + tiles + " -o '" + dir + "/merged.png'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("merged 8 tiles of 96x54"));
  CHECK(rt::test::read_file(dir + "/merged.png") == rt::test::read_file(dir + "/whole.png"));
  REQUIRE(rtcli("merge" + tiles + " -o '" + dir + "/merged.exr'").code == 0);
  CHECK(rt::test::read_file(dir + "/merged.exr") == rt::test::read_file(dir + "/whole.exr"));

  // What the tiles say about themselves.
  std::string error;
  const auto tile = rt::read_exr(dir + "/tile3.exr", 1 << 20, error);
  REQUIRE(tile);
  CHECK(tile->width == 96);
  CHECK(tile->window.x0 == 0);  // a band of whole rows
  CHECK(tile->window.x1 == 96);
  CHECK(tile->window.height() >= 1);
  CHECK(tile->full_float);
  CHECK(tile->attributes.at("rtcli:tile") == "3/8");
  CHECK(tile->attributes.at("rtcli:crop") ==
        "0," + std::to_string(tile->window.y0) + ",96," + std::to_string(tile->window.y1));
  CHECK(tile->attributes.at("rtcli:frame") == "0");
  CHECK(tile->attributes.at("rtcli:scene_hash").size() == 16);
  CHECK_THAT(tile->attributes.at("rtcli:settings"), Catch::Contains("size=96x54;seed="));
  REQUIRE(tile->layers.size() == 4);
  CHECK(tile->layers[0].channels == std::vector<std::string>{"R", "G", "B"});
  REQUIRE(tile->layer("albedo"));
  REQUIRE(tile->layer("normal"));
  REQUIRE(tile->layer("depth"));
  CHECK(tile->layer("normal")->channels == std::vector<std::string>{"X", "Y", "Z"});
  CHECK(tile->layer("depth")->channels == std::vector<std::string>{"Z"});
  // The normals are averages of unit vectors (shorter at an edge); the depth is one ray's distance
  // or, where it hits nothing, 1e10, never an average of the two.
  int background = 0, unit = 0;
  for (size_t p = 0; p < tile->layer("depth")->values.size(); ++p) {
    const float* n = &tile->layer("normal")->values[3 * p];
    const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const float d = tile->layer("depth")->values[p];
    CHECK(len <= 1.001f);
    CHECK(((d > 0.0f && d < 100.0f) || d == 1e10f));
    background += d == 1e10f;
    unit += len > 0.999f;
  }
  CHECK(background > 0);
  CHECK(unit > 0);

  // A missing tile is named, and nothing is written.
  std::string seven = tiles;
  seven.erase(seven.find(" '" + dir + "/tile5.exr'"), dir.size() + 13);
  r = rtcli("merge" + seven + " -o '" + dir + "/missing.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("tile 5/8 (rows ") && Catch::Contains(") is missing: render it with --tile 5/8"));
  CHECK_FALSE(std::filesystem::exists(dir + "/missing.png"));

  // A tile of another render (another seed), and tiles that overlap.
  REQUIRE(
      rtcli(kStill + " --exr-float --aov albedo,normal,depth --seed 9 --tile 5/8 -o '" + dir + "/other.exr'").code ==
      0);
  r = rtcli("merge" + seven + " '" + dir + "/other.exr' -o '" + dir + "/mixed.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("a different settings_hash") && Catch::Contains("seed=9 against seed="));
  REQUIRE(rtcli(kStill + " --exr-float --aov albedo,normal,depth --crop 0,30,96,40 -o '" + dir + "/band.exr'").code ==
          0);
  r = rtcli("merge" + tiles + " '" + dir + "/band.exr' -o '" + dir + "/twice.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("band.exr (x 0-95, y 30-39) overlap"));
  CHECK_FALSE(std::filesystem::exists(dir + "/twice.png"));
}

TEST_CASE("cli: half-float tiles merge into the half EXR a whole render writes", "[cli][split]") {
  const std::string dir = rt::test::fresh_folder("split-half");
  REQUIRE(rtcli(kStill + " -o '" + dir + "/whole.exr'").code == 0);
  std::string tiles;
  for (int i = 0; i < 3; ++i) {
    const std::string crop = i == 0 ? "0,0,50,54" : i == 1 ? "50,0,96,20" : "50,20,96,54";
    REQUIRE(rtcli(kStill + " --crop " + crop + " -o '" + dir + "/c" + std::to_string(i) + ".exr'").code == 0);
    tiles += " '" + dir + "/c" + std::to_string(i) + ".exr'";
  }
  const auto r = rtcli("merge" + tiles + " -o '" + dir + "/merged.exr'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK(rt::test::read_file(dir + "/merged.exr") == rt::test::read_file(dir + "/whole.exr"));
}

TEST_CASE("cli: frame chunks encode into the GIF a whole render writes, --skip-existing resumes", "[cli][split]") {
  const std::string dir = rt::test::fresh_folder("split-frames");
  const std::string anim = "render scenes/turntable.json --frames 0-11 --width 48 --height 36 -q";
  REQUIRE(rtcli(anim + " -o '" + dir + "/whole.gif'").code == 0);
  for (int c = 0; c < 4; ++c)
    REQUIRE(rtcli(anim + " --chunk " + std::to_string(c) + "/4 -o '" + dir + "/f_####.png'").code == 0);
  auto r = rtcli("encode '" + dir + "'/f_*.png --fps 30 -o '" + dir + "/encoded.gif'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK(rt::test::read_file(dir + "/encoded.gif") == rt::test::read_file(dir + "/whole.gif"));

  // Frame 5 lost, frame 6 cut short: only they are rendered again.
  std::filesystem::remove(dir + "/f_0005.png");
  const std::string six = rt::test::read_file(dir + "/f_0006.png");
  rt::test::write_file("split-frames/f_0006.png", six.substr(0, six.size() / 2));
  r = rtcli("render scenes/turntable.json --frames 0-11 --width 48 --height 36 --skip-existing -o '" + dir +
            "/f_####.png'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("10 of 12 frames' outputs are already there and complete (--skip-existing)"));
  CHECK_THAT(r.output, Catch::Contains("frames 5-6 (2)"));
  CHECK(rt::test::read_file(dir + "/f_0006.png") == six);
  // Everything there: nothing to do.
  r = rtcli(anim + " --skip-existing -o '" + dir + "/f_####.png'");
  CHECK(r.code == 0);
}

TEST_CASE("cli: --tile auto and --chunk auto take a Slurm array task's share", "[cli][split]") {
  const std::string dir = rt::test::fresh_folder("split-auto");
  const std::string env = "SLURM_ARRAY_TASK_ID=12 SLURM_ARRAY_TASK_MIN=10 SLURM_ARRAY_TASK_COUNT=4";
  auto r = rtcli(kStill + " --tile auto -o '" + dir + "/t.exr'", RTCLI_SOURCE_DIR, env);
  INFO(r.output);
  REQUIRE(r.code == 0);
  std::string error;
  const auto tile = rt::read_exr(dir + "/t.exr", 1 << 20, error);
  REQUIRE(tile);
  CHECK(tile->attributes.at("rtcli:tile") == "2/4");
  r = rtcli("render scenes/turntable.json --frames 0-9 --width 16 --height 12 --chunk auto -o '" + dir + "/f_####.png'",
            RTCLI_SOURCE_DIR, env);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("frames 6-7 (2)"));  // 3, 3, 2, 2 frames: task 2 of 4 has frames 6-7
  r = rtcli(kStill + " --tile auto -o '" + dir + "/t.exr'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--tile auto: expected a Slurm job array's SLURM_ARRAY_TASK_ID"));
}

TEST_CASE("cli: bad parts and bad tiles are refused with the reason", "[cli][split]") {
  const std::string dir = rt::test::fresh_folder("split-bad");
  const std::string out = " -o '" + dir + "/x.exr'";
  const std::pair<std::string, std::string> cases[] = {
      {" --crop 0,0,97,10" + out, "--crop: expected 0 <= x0 < x1 <= 96"},
      {" --crop 1,2,3" + out, "--crop: expected x0,y0,x1,y1"},
      {" --tile 8/8" + out, "--tile: expected I/N with 0 <= I < N"},
      {" --tile 0/60" + out, "60 bands of rows for an image 54 rows high"},
      {" --aov albedo -o '" + dir + "/x.png'", "--aov applies to EXR output"},
      {" --aov albedo,shadow" + out, "--aov: expected layers among albedo, normal, depth"},
      {" --chunk 0/2 -o '" + dir + "/x.gif'", "--chunk renders a share of the frames"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = rtcli(kStill + args);
    INFO(args << "\n" << r.output);
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains(message));
  }
  rt::test::write_file("split-bad/broken.exr", "v/1\x01 not really");
  const auto r = rtcli("merge '" + dir + "/broken.exr' -o '" + dir + "/m.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("broken.exr: not a readable OpenEXR image"));
}

TEST_CASE("cli: farm slurm --dry-run writes the two job scripts, options the farm sets are refused", "[cli][split]") {
  const std::string dir = rt::test::fresh_folder("split-farm");
  auto r = rtcli(
      "farm slurm scenes/antialias.json --tasks 6 --cpus 2 --partition gpu --time 0:30:00 --width 96 "
      "--dry-run -o '" +
      dir + "/still.png'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const std::string render = rt::test::read_file(dir + "/still-farm/render.sbatch");
  CHECK_THAT(render, Catch::Contains("#SBATCH --array=0-5") && Catch::Contains("#SBATCH --cpus-per-task=2") &&
                         Catch::Contains("#SBATCH --partition=gpu") && Catch::Contains("#SBATCH --time=0:30:00") &&
                         Catch::Contains("#SBATCH --requeue") && Catch::Contains("'--width' '96' --threads 2") &&
                         Catch::Contains("--skip-existing") && Catch::Contains("--tile \"$share\"") &&
                         Catch::Contains("share=\"$SLURM_ARRAY_TASK_ID/6\""));
  const std::string finish = rt::test::read_file(dir + "/still-farm/finish.sbatch");
  CHECK_THAT(finish, Catch::Contains(" merge '" + dir + "/still-farm/tiles'/tile_*.exr -o '" + dir + "/still.png'"));
  CHECK_THAT(r.output, Catch::Contains("not submitted (--dry-run)"));
  CHECK_FALSE(std::filesystem::exists(dir + "/still-farm/jobs"));

  // An animation: frame chunks and the encode; --dither goes to the GIF.
  r = rtcli("farm slurm scenes/turntable.json --tasks 3 --frames 0-11 --dither --dry-run -q -o '" + dir + "/turn.gif'");
  REQUIRE(r.code == 0);
  CHECK_THAT(rt::test::read_file(dir + "/turn-farm/render.sbatch"), Catch::Contains("'--frames' '0-11'") &&
                                                                        Catch::Contains("--chunk \"$share\"") &&
                                                                        Catch::Contains("frame_######.exr"));
  CHECK_THAT(rt::test::read_file(dir + "/turn-farm/finish.sbatch"),
             Catch::Contains(" encode ") && Catch::Contains("--dither"));

  for (const char* owned : {"--threads 4", "--tile 0/2", "--stats s.json", "--exr-float"}) {
    r = rtcli("farm slurm scenes/antialias.json --tasks 2 --dry-run " + std::string(owned) + " -o '" + dir + "/x.png'");
    INFO(owned << "\n" << r.output);
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("is set by the farm for each task; leave it out"));
  }
  r = rtcli("farm slurm tests/data/bad/key-bump-strength-typo.json --tasks 2 --dry-run -o '" + dir + "/y.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("is not a valid scene; nothing submitted"));
}
