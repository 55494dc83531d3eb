// `rtcli farm slurm SCENE --tasks N -o OUT [--partition P] [--time T] [--cpus C] [--farm-dir DIR]
//   [--dry-run] [render options...]`: writes the Slurm job scripts for a render split into N tasks
// (cli/farm/slurm_jobs.h) into DIR (default: OUT's name + "-farm", beside it), prints them, and
// submits them with sbatch --parsable (the finishing job with --dependency=afterok) unless --dry-run.
// `rtcli farm status DIR`: the jobs' state (squeue), the tiles or frames done, each task's time.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt {

struct FarmSlurmCommand {
  std::string scene;
  std::string output;
  int tasks = 1;
  int cpus = 1;
  std::optional<std::string> partition, time, farm_dir;
  bool dry_run = false;
  bool quiet = false;
  std::vector<std::string> render_options;  // the rest of the command line
};

struct FarmStatusCommand {
  std::string farm_dir;
};

int run_farm_slurm(const FarmSlurmCommand& cmd);
int run_farm_status(const FarmStatusCommand& cmd);

}  // namespace rt
