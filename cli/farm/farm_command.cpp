#include "cli/farm/farm_command.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <set>
#include <sstream>

#include "cli/exit_codes.h"
#include "cli/farm/slurm_jobs.h"
#include "cli/frame_output.h"
#include "cli/report.h"
#include "cli/scene_loading.h"
#include "io/image/atomic_file.h"
#include "io/scene_validator.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

// Options the farm sets on every task itself.
const std::set<std::string> kFarmOwned = {"-o", "--output", "--tile", "--crop", "--chunk", "--threads", "--skip-existing",
                                          "--exr-float", "--stats", "--samples-debug", "--aa-debug"};

bool write_text(const std::string& path, const std::string& text, std::string& error) {
  return write_file_atomically(path, std::vector<uint8_t>(text.begin(), text.end()), error);
}

// A command's standard output, and whether it exited 0.
bool run_command(const std::string& command, std::string& out) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return false;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  return pclose(pipe) == 0;
}

std::string default_farm_dir(const std::string& output) {
  const fs::path p(output);
  std::string stem = p.stem().string();
  while (!stem.empty() && (stem.back() == '#' || stem.back() == '_' || stem.back() == '-')) stem.pop_back();
  return (p.parent_path() / ((stem.empty() ? "render" : stem) + "-farm")).string();
}

// sbatch --parsable prints "ID" or "ID;CLUSTER".
std::optional<std::string> submit(const std::string& args, std::string& error) {
  std::string out;
  if (!run_command("sbatch --parsable " + args + " 2>&1", out)) {
    error = "sbatch " + args + " failed: " + out;
    return std::nullopt;
  }
  const std::string id = out.substr(0, out.find_first_of(";\n"));
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
    error = "sbatch printed no job id: " + out;
    return std::nullopt;
  }
  return id;
}

}  // namespace

int run_farm_slurm(const FarmSlurmCommand& cmd) {
  const auto fail = [](const std::string& message, int code = kExitBadInput) {
    std::fprintf(stderr, "rtcli: error: farm slurm: %s\n", message.c_str());
    return code;
  };
  for (const std::string& o : cmd.render_options) {
    const std::string name = o.substr(0, o.find('='));
    if (kFarmOwned.count(name)) return fail(name + " is set by the farm for each task; leave it out");
  }
  std::string error;
  const std::optional<OutputKind> kind = output_kind(cmd.output, error);
  if (!kind || *kind == OutputKind::kJpeg) return fail("-o: expected .png, .exr, .gif or NAME_####.png/.exr, found \"" + cmd.output + "\"");
  const Diagnostics diags = validate_file(cmd.scene, cli_load_options(0, std::nullopt, false));
  if (diags.has_errors()) {
    print_diagnostics(stderr, diags);
    return fail(cmd.scene + " is not a valid scene; nothing submitted");
  }
  SlurmJobSpec spec;
  char self[4096];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return fail("cannot find the rtcli binary's path", kExitFailure);
  spec.rtcli = std::string(self, static_cast<size_t>(n));
  spec.scene = fs::absolute(cmd.scene).lexically_normal().string();
  spec.output = fs::absolute(cmd.output).lexically_normal().string();
  spec.farm_dir = fs::absolute(cmd.farm_dir.value_or(default_farm_dir(cmd.output))).lexically_normal().string();
  spec.tasks = cmd.tasks;
  spec.cpus = cmd.cpus;
  spec.partition = cmd.partition;
  spec.time = cmd.time;
  for (const std::string& o : cmd.render_options) {
    if (o == "--dither") spec.dither = true;
    else spec.render_options.push_back(o);
  }
  std::error_code ec;
  for (const char* sub : {"logs", farm_work(spec) == FarmWork::kTiles ? "tiles" : "frames"}) {
    fs::create_directories(spec.farm_dir + "/" + sub, ec);
    if (ec) return fail("cannot make " + spec.farm_dir + "/" + sub + ": " + ec.message(), kExitFailure);
  }
  const std::string render = render_script(spec), finish = finish_script(spec);
  const std::string render_path = spec.farm_dir + "/render.sbatch", finish_path = spec.farm_dir + "/finish.sbatch";
  if (!write_text(render_path, render, error) || (!finish.empty() && !write_text(finish_path, finish, error)))
    return fail(error, kExitFailure);
  if (!cmd.quiet) {
    std::printf("# %s\n%s", render_path.c_str(), render.c_str());
    if (!finish.empty()) std::printf("# %s\n%s", finish_path.c_str(), finish.c_str());
  }
  if (cmd.dry_run) {
    std::printf("not submitted (--dry-run): sbatch --parsable %s", shell_quote(render_path).c_str());
    if (!finish.empty()) std::printf(", then sbatch --dependency=afterok:ID %s", shell_quote(finish_path).c_str());
    std::printf("\n");
    return kExitSuccess;
  }
  const std::optional<std::string> array = submit(shell_quote(render_path), error);
  if (!array) return fail(error, kExitFailure);
  std::string jobs = "render " + *array + "\n";
  if (!finish.empty()) {
    const std::optional<std::string> after = submit("--dependency=afterok:" + *array + " " + shell_quote(finish_path), error);
    if (!after) return fail(error + " (the array " + *array + " was submitted)", kExitFailure);
    jobs += "finish " + *after + "\n";
  }
  if (!write_text(spec.farm_dir + "/jobs", jobs, error)) return fail(error, kExitFailure);
  std::printf("submitted %s", jobs.c_str());
  std::printf("progress: rtcli farm status %s   (or squeue -j %s, sacct -j %s)\n", shell_quote(spec.farm_dir).c_str(),
              array->c_str(), array->c_str());
  return kExitSuccess;
}

int run_farm_status(const FarmStatusCommand& cmd) {
  std::ifstream jobs_file(cmd.farm_dir + "/jobs");
  if (!jobs_file) {
    std::fprintf(stderr, "rtcli: error: farm status: %s/jobs not found (was the render submitted with rtcli farm slurm?)\n",
                 cmd.farm_dir.c_str());
    return kExitBadInput;
  }
  std::string role, id, ids;
  while (jobs_file >> role >> id) ids += (ids.empty() ? "" : ",") + id;
  std::string out;
  if (run_command("squeue -h -j " + ids + " -o '%i %j %T %M %R' 2>&1", out))
    std::printf("queued or running (squeue):\n%s", out.empty() ? "  none\n" : out.c_str());
  else
    std::printf("squeue failed: %s", out.c_str());
  for (const char* sub : {"tiles", "frames"}) {
    std::error_code ec;
    if (!fs::is_directory(cmd.farm_dir + "/" + sub, ec)) continue;
    size_t done = 0;
    for (const auto& e : fs::directory_iterator(cmd.farm_dir + "/" + sub, ec)) done += e.path().extension() == ".exr";
    std::printf("%s done: %zu\n", sub, done);
  }
  // Each task's summary line from its log.
  std::error_code ec;
  std::vector<std::string> logs;
  for (const auto& e : fs::directory_iterator(cmd.farm_dir + "/logs", ec)) logs.push_back(e.path().string());
  std::sort(logs.begin(), logs.end());
  for (const std::string& log : logs) {
    std::ifstream in(log);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("rendered ", 0) == 0 || line.rfind("merged ", 0) == 0 || line.rfind("encoded ", 0) == 0 ||
          line.find("error") != std::string::npos)
        std::printf("%s: %s\n", fs::path(log).filename().c_str(), line.c_str());
  }
  return kExitSuccess;
}

}  // namespace rt
