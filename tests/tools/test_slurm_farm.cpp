// rtcli farm on a real Slurm: a one-node cluster on loopback (tools/slurm/cluster.sh: munged,
// slurmctld, slurmd, no systemd), started as root for this test and stopped by PID at its end.
// A still as 8 tile tasks plus the dependent merge, an animation as 4 frame chunks plus the
// dependent encode, both byte-identical to the local render; a task cancelled while it runs:
// merge names the missing tile and exits 2, and submitting that task again completes the image.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

using rt::test::rtcli;
using rt::test::run_shell;

namespace {

// The cluster for the test's lifetime.
class Cluster {
 public:
  explicit Cluster(std::string dir) : dir_(std::move(dir)) {
    const auto r = run_shell("'" + rt::test::source_path("tools/slurm/cluster.sh") + "' start '" + dir_ + "' 2>&1");
    up_ = r.code == 0;
    message_ = r.output;
  }
  ~Cluster() { run_shell("'" + rt::test::source_path("tools/slurm/cluster.sh") + "' stop '" + dir_ + "' 2>&1"); }
  bool up() const { return up_; }
  const std::string& message() const { return message_; }
  // A command with the cluster's configuration.
  std::string env() const { return "SLURM_CONF='" + dir_ + "/slurm.conf' "; }

 private:
  std::string dir_;
  bool up_ = false;
  std::string message_;
};

// Waits until none of the jobs is queued or running (at most `seconds`).
bool wait_for(const Cluster& c, const std::string& jobs, int seconds) {
  for (int i = 0; i < seconds * 5; ++i) {
    const auto r = run_shell(c.env() + "squeue -h -j " + jobs + " 2>&1");
    if (r.code == 0 && r.output.empty()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return false;
}

// "submitted render 12\nfinish 13\n" -> "12", "13".
std::string job_id(const std::string& output, const std::string& role) {
  const size_t at = output.find(role + " ");
  if (at == std::string::npos) return "";
  const size_t start = at + role.size() + 1;
  return output.substr(start, output.find_first_not_of("0123456789", start) - start);
}

std::string fresh(const std::string& name) {
  const std::string dir = rt::test::output_path(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("farm: tiles, frame chunks and a cancelled task on a one-node Slurm cluster", "[farm][slurm]") {
  if (::geteuid() != 0 || run_shell("command -v slurmctld slurmd munged sbatch pgrep >/dev/null 2>&1").code != 0) {
    WARN(
        "Slurm is not installed (tools/install-deps.sh --tests installs slurm-wlm, munge and procps) or this is not "
        "root: "
        "the farm test on a real cluster is skipped");
    return;
  }
  const Cluster cluster(fresh("slurm-cluster"));
  INFO(cluster.message());
  REQUIRE(cluster.up());
  const std::string dir = fresh("slurm-farm");
  const std::string env = cluster.env();

  // A still in 8 bands of rows, then the merge.
  const std::string still = "scenes/antialias.json --width 160 --height 90";
  REQUIRE(rtcli("render " + still + " -q -o '" + dir + "/local.png'").code == 0);
  auto r = rtcli("farm slurm " + still + " --tasks 8 -q -o '" + dir + "/still.png'", RTCLI_SOURCE_DIR, env);
  INFO(r.output);
  REQUIRE(r.code == 0);
  const std::string array = job_id(r.output, "render"), merge = job_id(r.output, "finish");
  REQUIRE_FALSE(array.empty());
  REQUIRE_FALSE(merge.empty());
  REQUIRE(wait_for(cluster, array + "," + merge, 120));
  CHECK(rt::test::read_file(dir + "/still.png") == rt::test::read_file(dir + "/local.png"));
  r = rtcli("farm status '" + dir + "/still-farm'", RTCLI_SOURCE_DIR, env);
  CHECK_THAT(r.output, Catch::Contains("tiles done: 8") && Catch::Contains("merged 8 tiles of 160x90"));

  // 12 frames in 4 chunks, then the GIF.
  const std::string anim = "scenes/turntable.json --frames 0-11 --width 64 --height 48";
  REQUIRE(rtcli("render " + anim + " -q -o '" + dir + "/local.gif'").code == 0);
  r = rtcli("farm slurm " + anim + " --tasks 4 -q -o '" + dir + "/turn.gif'", RTCLI_SOURCE_DIR, env);
  INFO(r.output);
  REQUIRE(r.code == 0);
  REQUIRE(wait_for(cluster, job_id(r.output, "render") + "," + job_id(r.output, "finish"), 120));
  CHECK(rt::test::read_file(dir + "/turn.gif") == rt::test::read_file(dir + "/local.gif"));

  // A path-traced still whose tasks take a few seconds (3.5 s each on one thread of a 2-vCPU machine
  // at 4096 spp): task 3 cancelled while its rtcli runs. Not as soon as squeue says RUNNING: that is
  // the allocation, and a cancel that reaches slurmctld before slurmd has launched the task can lose
  // the race (the controller records it cancelled, the node runs it to the end and writes the tile:
  // CI saw it once). rtcli's command line names its tile; "[t]ile" keeps the shell out of the match.
  const std::string slow = "scenes/cornell_box.json --width 96 --height 96 --spp 4096";
  r = rtcli("farm slurm " + slow + " --tasks 8 -q -o '" + dir + "/box.png'", RTCLI_SOURCE_DIR, env);
  INFO(r.output);
  REQUIRE(r.code == 0);
  const std::string box = job_id(r.output, "render"), box_merge = job_id(r.output, "finish");
  const std::string task_3_runs = "pgrep -f -- 'box-farm/tiles/[t]ile_3[.]exr' >/dev/null";
  bool cancelled = false;
  for (int i = 0; i < 1500 && !cancelled; ++i) {
    if (run_shell(task_3_runs).code == 0) cancelled = run_shell(env + "scancel " + box + "_3").code == 0;
    else std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  REQUIRE(cancelled);
  REQUIRE(wait_for(cluster, box, 180));
  for (int i = 0; i < 150 && run_shell(task_3_runs).code == 0; ++i)  // the signalled process has exited
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  CHECK(run_shell(task_3_runs).code != 0);
  run_shell(env + "scancel " + box_merge);  // its dependency can never be met now
  CHECK_FALSE(std::filesystem::exists(dir + "/box-farm/tiles/tile_3.exr"));
  r = rtcli("merge '" + dir + "/box-farm/tiles'/tile_*.exr -o '" + dir + "/box.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("tile 3/8 (rows ") && Catch::Contains(") is missing: render it with --tile 3/8"));
  CHECK_FALSE(std::filesystem::exists(dir + "/box.png"));
  // Only that task again: its band the same as a local render of that band (the still above shows
  // that merged bands are the whole image); then the merge completes the image.
  const auto again = run_shell(env + "sbatch --parsable --array=3 '" + dir + "/box-farm/render.sbatch' 2>&1");
  INFO(again.output);
  REQUIRE(again.code == 0);
  REQUIRE(wait_for(cluster, again.output.substr(0, again.output.find_first_of(";\n")), 180));
  // The farm names the scene by its absolute path, which the EXR's metadata records.
  REQUIRE(rtcli("render \"$(pwd -P)\"/" + slow + " -q --exr-float --tile 3/8 -o '" + dir + "/tile_3-local.exr'").code ==
          0);
  CHECK(rt::test::read_file(dir + "/box-farm/tiles/tile_3.exr") == rt::test::read_file(dir + "/tile_3-local.exr"));
  r = rtcli("merge '" + dir + "/box-farm/tiles'/tile_*.exr -o '" + dir + "/box.png'");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK(std::filesystem::exists(dir + "/box.png"));
}
