#include "cli/farm/slurm_jobs.h"

#include <filesystem>

#include "cli/frame_output.h"

namespace rt {
namespace {

std::string header(const SlurmJobSpec& spec, const std::string& name, const std::string& log) {
  std::string s = "#!/bin/bash\n";
  s += "#SBATCH --job-name=" + name + "\n";
  s += "#SBATCH --output=" + spec.farm_dir + "/logs/" + log + "\n";
  if (spec.partition) s += "#SBATCH --partition=" + *spec.partition + "\n";
  if (spec.time) s += "#SBATCH --time=" + *spec.time + "\n";
  return s;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace

FarmWork farm_work(const SlurmJobSpec& spec) {
  std::string error;
  const std::optional<OutputKind> kind = output_kind(spec.output, error);
  return kind && is_single_image(*kind) ? FarmWork::kTiles : FarmWork::kFrames;
}

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string render_script(const SlurmJobSpec& spec) {
  const bool tiles = farm_work(spec) == FarmWork::kTiles;
  std::string s = header(spec, "rtcli-" + stem(spec.output), "render_%A_%a.log");
  s += "#SBATCH --array=0-" + std::to_string(spec.tasks - 1) + "\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(spec.cpus) + "\n";
  s += "#SBATCH --requeue\n";
  s += "# rtcli farm slurm: task I renders its " + std::string(tiles ? "band of rows" : "chunk of the frames") +
       " (I/" + std::to_string(spec.tasks) + ");\n# a task requeued or submitted again skips what it finished.\n";
  s += "set -euo pipefail\n";
  s += "share=\"$SLURM_ARRAY_TASK_ID/" + std::to_string(spec.tasks) + "\"\n";
  s += "exec " + shell_quote(spec.rtcli) + " render " + shell_quote(spec.scene);
  for (const std::string& o : spec.render_options) s += " " + shell_quote(o);
  s += " --threads " + std::to_string(spec.cpus) + " --skip-existing --stats " +
       shell_quote(spec.farm_dir + "/logs/task_") + "\"$SLURM_ARRAY_TASK_ID\"" + shell_quote(".json");
  std::string error;
  const std::optional<OutputKind> kind = output_kind(spec.output, error);
  if (tiles) {
    s += " --exr-float --tile \"$share\" -o " + shell_quote(spec.farm_dir + "/tiles/tile_") + "\"$SLURM_ARRAY_TASK_ID\"" +
         shell_quote(".exr");
  } else if (kind && is_sequence(*kind)) {
    s += " --chunk \"$share\" -o " + shell_quote(spec.output);
  } else {
    s += " --exr-float --chunk \"$share\" -o " + shell_quote(spec.farm_dir + "/frames/frame_######.exr");
  }
  return s + "\n";
}

std::string finish_script(const SlurmJobSpec& spec) {
  std::string error;
  const std::optional<OutputKind> kind = output_kind(spec.output, error);
  if (kind && is_sequence(*kind)) return "";
  const bool tiles = farm_work(spec) == FarmWork::kTiles;
  std::string s = header(spec, "rtcli-" + stem(spec.output) + (tiles ? "-merge" : "-encode"),
                         tiles ? "merge_%j.log" : "encode_%j.log");
  s += "# rtcli farm slurm: after every task of the array succeeded (--dependency=afterok).\n";
  s += "set -euo pipefail\n";
  if (tiles)
    s += "exec " + shell_quote(spec.rtcli) + " merge " + shell_quote(spec.farm_dir + "/tiles") + "/tile_*.exr -o " +
         shell_quote(spec.output) + "\n";
  else
    s += "exec " + shell_quote(spec.rtcli) + " encode " + shell_quote(spec.farm_dir + "/frames") + "/frame_*.exr" +
         (spec.dither ? " --dither" : "") + " -o " + shell_quote(spec.output) + "\n";
  return s;
}

}  // namespace rt
