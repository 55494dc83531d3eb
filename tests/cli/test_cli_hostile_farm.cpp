// rtcli farm against hostile values (issue 36): every value that reaches a job script is checked
// (a newline in --partition was a shell command on the cluster), the farm folder's jobs file is
// untrusted (farm status ran what it held through popen), counts are checked against the image,
// and an animation's frames are encoded in their numeric order, negative ones included.
#include <sys/stat.h>

#include <filesystem>

#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;
using rt::test::output_path;
using rt::test::read_file;
using rt::test::rtcli;
using rt::test::Run;

TEST_CASE("cli farm: a value that would break out of a job script is refused by name, and nothing is written",
          "[cli][farm][hostile]") {
  const std::string dir = rt::test::fresh_folder("farm-hostile");
  // Each as the shell passes it: single-quoted, a real newline inside.
  const struct {
    std::string args, expected;
  } cases[] = {
      {"--partition 'gpu\ntouch " + dir + "/pwned'", "--partition: expected no control characters"},
      {"--time '1:00:00\ntouch " + dir + "/pwned'", "--time: expected no control characters"},
      {"--partition ''", "--partition: expected a value, found \"\""},
      {"--time ''", "--time: expected a value"},
      {"--partition 'gpu --wrap=id'", "--partition: expected a partition name"},
      {"--time 'now;id'", "--time: expected a Slurm time"},
      {"--farm-dir '" + dir + "/a\nb'", "the farm folder: expected no control characters"},
      {"--farm-dir '" + dir + "/with space'", "the farm folder: expected no spaces, quotes, backslashes or '%'"},
      {"--farm-dir '" + dir + "/job%j'", "'%' is a Slurm file-name pattern"},
      {"--width '96\nid'", "render option: expected no control characters"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const Run r =
        rtcli("farm slurm scenes/antialias.json --tasks 2 --dry-run " + c.args + " -o '" + dir + "/still.png'");
    INFO(r.output);
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains(c.expected) && Catch::Contains("nothing written or submitted"));
    CHECK_FALSE(fs::exists(dir + "/still-farm"));
    CHECK_FALSE(fs::exists(dir + "/pwned"));
  }
  // The output's own name: a newline there is refused too.
  Run r = rtcli("farm slurm scenes/antialias.json --tasks 2 --dry-run -o '" + dir + "/a\nb.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("-o: expected no control characters"));
  // A job name made of the output's stem keeps Slurm's safe characters only.
  r = rtcli("farm slurm scenes/antialias.json --tasks 2 --dry-run -q -o '" + dir + "/it'\"'\"'s.png' --farm-dir '" +
            dir + "/f'");
  REQUIRE(r.code == 0);
  CHECK_THAT(read_file(dir + "/f/render.sbatch"), Catch::Contains("#SBATCH --job-name=rtcli-it_s\n"));
}

TEST_CASE("cli farm: counts are named when out of range, and a still gets no more tasks than rows",
          "[cli][farm][errors]") {
  const std::string dir = rt::test::fresh_folder("farm-counts");
  for (const char* count : {"--tasks 0", "--tasks 100001", "--tasks abc", "--tasks 2 --cpus 0"}) {
    INFO(count);
    const Run r = rtcli("farm slurm scenes/antialias.json " + std::string(count) + " --dry-run -o '" + dir + "/s.png'");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("expected a whole number from 1 to"));
    CHECK_THAT(r.output, !Catch::Contains("unknown option"));
  }
  Run r = rtcli("farm slurm scenes/antialias.json --tasks 200 --height 100 --dry-run -o '" + dir + "/s.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("--tasks 200: a still is split into bands of rows, and the image is 100 rows high"));
  CHECK_FALSE(fs::exists(dir + "/s-farm"));
  r = rtcli("farm slurm scenes/antialias.json --tasks 100 --height=100 --dry-run -q -o '" + dir + "/s.png'");
  CHECK(r.code == 0);
}

TEST_CASE("cli farm: status reads job ids as digits only, never through a shell", "[cli][farm][hostile]") {
  const std::string dir = rt::test::fresh_folder("farm-status");
  const std::string pwned = dir + "/pwned";
  for (const std::string& jobs :
       std::vector<std::string>{"render 1;touch " + pwned + "\n", "render $(touch " + pwned + ")\n", "render 1 2\n",
                                "finish 12a\n", "submit 5\n"}) {
    INFO(jobs);
    rt::test::write_file("farm-status/jobs", jobs);
    const Run r = rtcli("farm status '" + dir + "'");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("/jobs:1: expected \"render ID\" or \"finish ID\""));
    CHECK_FALSE(fs::exists(pwned));
  }
  rt::test::write_file("farm-status/jobs", "\n");
  CHECK(rtcli("farm status '" + dir + "'").code == 2);
  // A named pipe as the jobs file is refused, not read forever.
  fs::remove(dir + "/jobs");
  REQUIRE(::mkfifo((dir + "/jobs").c_str(), 0600) == 0);
  const Run r = rtcli("farm status '" + dir + "'", RTCLI_SOURCE_DIR, "timeout 10");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("named pipe"));
}

TEST_CASE("cli farm: an animation's frames are encoded in numeric order, negative ones included", "[cli][farm]") {
  const std::string dir = rt::test::fresh_folder("farm-negative");
  Run r = rtcli("farm slurm scenes/turntable.json --tasks 2 --frames=-3-2 --width 16 --height 12 --dry-run -q -o '" +
                dir + "/turn.gif'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const std::string finish = read_file(dir + "/turn-farm/finish.sbatch");
  CHECK_THAT(finish, Catch::Contains("/frame_######.exr' --frames '-3-2' -o"));
  CHECK_THAT(finish, !Catch::Contains("frame_*"));
  // What that line runs: the six frames rendered as the tasks would, encoded in order -3..2, gives
  // the GIF a local render gives.
  r = rtcli("render scenes/turntable.json --frames=-3-2 --width 16 --height 12 --exr-float -q -o '" + dir +
            "/turn-farm/frames/frame_######.exr'");
  REQUIRE(r.code == 0);
  r = rtcli("encode '" + dir + "/turn-farm/frames/frame_######.exr' --frames=-3-2 -q -o '" + dir + "/turn.gif'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  r = rtcli("render scenes/turntable.json --frames=-3-2 --width 16 --height 12 -q -o '" + dir + "/local.gif'");
  REQUIRE(r.code == 0);
  CHECK(read_file(dir + "/turn.gif") == read_file(dir + "/local.gif"));
  // --frames fills one pattern only.
  r = rtcli("encode a.png b.png --frames 1-2 -o '" + dir + "/x.gif'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--frames fills one NAME_####.png or NAME_####.exr pattern"));
}
