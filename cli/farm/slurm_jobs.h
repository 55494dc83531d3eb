// The two Slurm batch scripts `rtcli farm slurm` writes for a render (docs/cluster.md):
//   render.sbatch  a job array of N tasks, each `rtcli render` of its share: a band of rows
//                  (--tile I/N, into FARM/tiles/tile_I.exr) for a still, a chunk of the frames
//                  (--chunk I/N, into FARM/frames/frame_####.exr, or the numbered files asked
//                  for) for an animation; --skip-existing, so that a requeued task resumes;
//                  each task's figures (--stats) in FARM/logs/task_I.json;
//   finish.sbatch  `rtcli merge` of the tiles, or `rtcli encode` of the frames into the GIF, run
//                  after every task succeeded (sbatch --dependency=afterok:ARRAY); none when
//                  the output is the numbered frames themselves.
// Everything lives on a file system every node sees: the rtcli binary, the scene and its files,
// and the farm folder.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt {

struct SlurmJobSpec {
  std::string rtcli;                        // absolute path of the binary the nodes run
  std::string scene;                        // absolute
  std::vector<std::string> render_options;  // passed to every task's rtcli render as they are
  std::string output;                       // absolute: .png/.exr (a still), .gif or NAME_####.png/.exr
  std::string farm_dir;                     // absolute: scripts, tiles or frames, logs
  int tasks = 1;
  int cpus = 1;  // per task: --cpus-per-task and rtcli's --threads
  std::optional<std::string> partition, time;
  bool dither = false;  // the GIF's (moved from the render options to encode)
  std::string frames;   // an animation's frames (FrameList::text), for encode
};

enum class FarmWork { kTiles, kFrames };

// Tiles for a single image, frame chunks for a GIF or numbered frames.
FarmWork farm_work(const SlurmJobSpec& spec);

// 'text' quoted for a POSIX shell.
std::string shell_quote(const std::string& text);

// Why `value` (for `what`: "--partition", "the farm folder", ...) cannot go into a job script, or ""
// when it can. No value may hold a control character (a newline would start a shell command on
// the cluster); `#SBATCH` values are read by sbatch without a shell, so they hold none of
// whitespace, quotes, backslashes or '%' (a Slurm file-name pattern) either; a partition is
// Slurm's name characters (and commas: a list), a time Slurm's digits, ':' and '-'.
enum class JobValue { kShellWord, kSbatchPath, kPartition, kTime };
std::string job_value_problem(const std::string& what, const std::string& value, JobValue kind);

// The problems of every value of `spec` that reaches a script (empty: none).
std::vector<std::string> job_spec_problems(const SlurmJobSpec& spec);

std::string render_script(const SlurmJobSpec& spec);
// Empty when nothing follows the array (numbered frames are the output).
std::string finish_script(const SlurmJobSpec& spec);

}  // namespace rt
