#include "cli/farm/farm_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "cli/common/child_process.h"
#include "cli/common/exit_codes.h"
#include "cli/common/report.h"
#include "cli/common/scene_loading.h"
#include "cli/farm/slurm_jobs.h"
#include "cli/frames/frame_list.h"
#include "cli/frames/frame_output.h"
#include "io/base/atomic_file.h"
#include "io/base/input_file.h"
#include "io/scene_loader.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

// A Slurm job id as sbatch --parsable prints it: digits only.
bool is_job_id(const std::string& id) {
  return !id.empty() && id.size() <= 20 && id.find_first_not_of("0123456789") == std::string::npos;
}

// Options the farm sets on every task itself.
const std::set<std::string> kFarmOwned = {"-o",      "--output",        "--tile",          "--crop",
                                          "--chunk", "--threads",       "--skip-existing", "--exr-float",
                                          "--stats", "--samples-debug", "--aa-debug"};

bool write_text(const std::string& path, const std::string& text, std::string& error) {
  return write_file_atomically(path, std::vector<uint8_t>(text.begin(), text.end()), error);
}

// The value of a render option passed on to the tasks ("--height 90" or "--height=90"), the last
// one given; nothing when it is not there.
std::optional<std::string> option_value(const std::vector<std::string>& options, const std::string& name) {
  std::optional<std::string> value;
  for (size_t i = 0; i < options.size(); ++i) {
    if (options[i] == name && i + 1 < options.size()) value = options[i + 1];
    else if (options[i].rfind(name + "=", 0) == 0) value = options[i].substr(name.size() + 1);
  }
  return value;
}

std::string default_farm_dir(const std::string& output) {
  const fs::path p(output);
  std::string stem = p.stem().string();
  while (!stem.empty() && (stem.back() == '#' || stem.back() == '_' || stem.back() == '-')) stem.pop_back();
  return (p.parent_path() / ((stem.empty() ? "render" : stem) + "-farm")).string();
}

// sbatch --parsable prints "ID" or "ID;CLUSTER".
std::optional<std::string> submit(const std::vector<std::string>& args, std::string& error) {
  std::vector<std::string> command = {"sbatch", "--parsable"};
  command.insert(command.end(), args.begin(), args.end());
  std::string out;
  if (!run_program(command, out)) {
    error = "sbatch " + args.back() + " failed: " + out;
    return std::nullopt;
  }
  const std::string id = out.substr(0, out.find_first_of(";\n"));
  if (!is_job_id(id)) {
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
  if (!kind || *kind == OutputKind::kJpeg)
    return fail("-o: expected .png, .exr, .gif or NAME_####.png/.exr, found \"" + cmd.output + "\"");
  Diagnostics diags;
  const std::optional<LoadedScene> loaded = load_scene(cmd.scene, cli_load_options(1, std::nullopt, false), diags);
  if (!loaded || diags.has_errors()) {
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
  if (const std::vector<std::string> problems = job_spec_problems(spec); !problems.empty()) {
    for (const std::string& p : problems) std::fprintf(stderr, "rtcli: error: farm slurm: %s\n", p.c_str());
    return fail("nothing written or submitted");
  }
  if (farm_work(spec) == FarmWork::kTiles) {
    // Every task renders a band of at least one row (rtcli render --tile refuses more bands).
    int height = loaded->settings.height;
    if (const auto h = option_value(spec.render_options, "--height")) height = std::atoi(h->c_str());
    if (height > 0 && cmd.tasks > height)
      return fail("--tasks " + std::to_string(cmd.tasks) + ": a still is split into bands of rows, and the image is " +
                  std::to_string(height) + " rows high; give at most " + std::to_string(height) + " tasks");
  } else {
    // The frames every task shares, as rtcli render chooses them: --frames or --frame, else the
    // scene's animation; encode takes them in this order (a glob would order -1 before -2).
    const std::optional<std::string> given = option_value(spec.render_options, "--frames")
                                                 ? option_value(spec.render_options, "--frames")
                                                 : option_value(spec.render_options, "--frame");
    const Timeline& t = loaded->graph.timeline;
    const std::optional<FrameList> frames =
        given ? parse_frame_list(*given, error)
              : std::optional<FrameList>(loaded->graph.animated ? FrameList::range(t.first_frame, t.last_frame)
                                                                : FrameList::range(loaded->frame, loaded->frame));
    if (!frames) return fail("--frames: " + error);
    spec.frames = frames->text();
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
  const std::optional<std::string> array = submit({render_path}, error);
  if (!array) return fail(error, kExitFailure);
  std::string jobs = "render " + *array + "\n";
  if (!finish.empty()) {
    const std::optional<std::string> after = submit({"--dependency=afterok:" + *array, finish_path}, error);
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
  // Through the bounded reader: a regular file of a few lines, never a FIFO or a device.
  std::string why;
  const std::optional<std::string> jobs_text = read_input_text(cmd.farm_dir + "/jobs", 4096, why);
  if (!jobs_text) {
    std::fprintf(stderr, "rtcli: error: farm status: %s/jobs: %s (was the render submitted with rtcli farm slurm?)\n",
                 cmd.farm_dir.c_str(), why.c_str());
    return kExitBadInput;
  }
  std::istringstream jobs_file(*jobs_text);
  // The farm folder lives on shared storage: its jobs file is read as untrusted. Lines are
  // "render ID" and "finish ID", IDs digits only.
  std::string jobs_line, ids;
  for (int number = 1; std::getline(jobs_file, jobs_line) && number <= 16; ++number) {
    std::istringstream words(jobs_line);
    std::string role, id, extra;
    words >> role >> id;
    if (role.empty() && id.empty()) continue;
    if ((role != "render" && role != "finish") || !is_job_id(id) || (words >> extra)) {
      std::fprintf(stderr,
                   "rtcli: error: farm status: %s/jobs:%d: expected \"render ID\" or \"finish ID\" with ID a Slurm job "
                   "id (digits); the file was not written by rtcli farm slurm\n",
                   cmd.farm_dir.c_str(), number);
      return kExitBadInput;
    }
    ids += (ids.empty() ? "" : ",") + id;
  }
  if (ids.empty()) {
    std::fprintf(stderr, "rtcli: error: farm status: %s/jobs holds no job id\n", cmd.farm_dir.c_str());
    return kExitBadInput;
  }
  std::string out;
  if (run_program({"squeue", "-h", "-j", ids, "-o", "%i %j %T %M %R"}, out))
    std::printf("queued or running (squeue):\n%s", out.empty() ? "  none\n" : out.c_str());
  else std::printf("squeue failed: %s", out.c_str());
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
