#include "cli/farm/slurm_jobs.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

#include "cli/frames/frame_output.h"

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

// The job's name: the output's stem in Slurm's safe characters (it is only a label in squeue).
std::string stem(const std::string& path) {
  std::string name = std::filesystem::path(path).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return name;
}

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

std::string job_value_problem(const std::string& what, const std::string& value, JobValue kind) {
  const auto refuse = [&](const std::string& why) {
    std::string shown;
    for (const char c : value.substr(0, 60)) {
      const auto u = static_cast<unsigned char>(c);
      if (u < 0x20 || u == 0x7f) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02x", u);
        shown += hex;
      } else {
        shown += c;
      }
    }
    return what + ": " + why + ", found \"" + shown + (value.size() > 60 ? "...\"" : "\"");
  };
  if (value.empty()) return refuse("expected a value");
  for (const char c : value) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f)
      return refuse("expected no control characters (a newline in a job script starts a command on the cluster)");
  }
  switch (kind) {
    case JobValue::kShellWord: return "";  // shell_quote takes any other byte
    case JobValue::kSbatchPath:
      if (value.find_first_of(" \t\"'\\%") != std::string::npos)
        return refuse(
            "expected no spaces, quotes, backslashes or '%' (sbatch reads an #SBATCH path without a shell, and "
            "'%' is a Slurm file-name pattern): choose another folder with --farm-dir");
      return "";
    case JobValue::kPartition:
      for (const char c : value)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.' && c != ',')
          return refuse("expected a partition name (letters, digits, '_', '-', '.'; a list separated by ',')");
      return "";
    case JobValue::kTime:
      if (value == "UNLIMITED" || value == "INFINITE") return "";
      for (const char c : value)
        if (!std::isdigit(static_cast<unsigned char>(c)) && c != ':' && c != '-')
          return refuse("expected a Slurm time: minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS");
      return "";
  }
  return "";
}

std::vector<std::string> job_spec_problems(const SlurmJobSpec& spec) {
  std::vector<std::string> problems;
  const auto check = [&](const std::string& what, const std::string& value, JobValue kind) {
    const std::string p = job_value_problem(what, value, kind);
    if (!p.empty()) problems.push_back(p);
  };
  check("the rtcli binary's path", spec.rtcli, JobValue::kShellWord);
  check("the scene", spec.scene, JobValue::kShellWord);
  check("-o", spec.output, JobValue::kShellWord);
  check("the farm folder", spec.farm_dir, JobValue::kSbatchPath);
  for (const std::string& o : spec.render_options) check("render option", o, JobValue::kShellWord);
  if (spec.partition) check("--partition", *spec.partition, JobValue::kPartition);
  if (spec.time) check("--time", *spec.time, JobValue::kTime);
  return problems;
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
    s += " --exr-float --tile \"$share\" -o " + shell_quote(spec.farm_dir + "/tiles/tile_") +
         "\"$SLURM_ARRAY_TASK_ID\"" + shell_quote(".exr");
  } else if (kind && is_sequence(*kind)) {
    s += " --chunk \"$share\" -o " + shell_quote(spec.output);
  } else {
    s += " --exr-float --chunk \"$share\" -o " + shell_quote(spec.farm_dir + "/frames/frame_######.exr");
  }
  return s + "\n";
}

// The merge's denoising options: a tiled render asked to --denoise carries the denoiser's layers,
// and its merge denoises the whole image (cli/render/render_plan.cpp).
std::string merge_denoise_options(const SlurmJobSpec& spec) {
  const std::vector<std::string>& o = spec.render_options;
  for (size_t i = 0; i < o.size(); ++i) {
    if (o[i] == "--denoiser" && i + 1 < o.size()) return " --denoiser " + shell_quote(o[i + 1]);
    if (o[i].rfind("--denoiser=", 0) == 0) return " " + shell_quote(o[i]);
  }
  for (const std::string& option : o)
    if (option == "--denoise") return " --denoise";
  return "";
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
    s += "exec " + shell_quote(spec.rtcli) + " merge " + shell_quote(spec.farm_dir + "/tiles") + "/tile_*.exr" +
         merge_denoise_options(spec) + " -o " + shell_quote(spec.output) + "\n";
  else
    s += "exec " + shell_quote(spec.rtcli) + " encode " + shell_quote(spec.farm_dir + "/frames/frame_######.exr") +
         " --frames " + shell_quote(spec.frames) + (spec.dither ? " --dither" : "") + " -o " +
         shell_quote(spec.output) + "\n";
  return s;
}

}  // namespace rt
