#include "cli/watch/watch_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <thread>

#include "cli/common/exit_codes.h"
#include "cli/common/interrupt.h"
#include "cli/common/isa_choice.h"
#include "cli/common/number_checks.h"
#include "cli/common/report.h"
#include "cli/common/scene_loading.h"
#include "cli/render/settings_overrides.h"
#include "cli/watch/preview_renderer.h"
#include "cli/watch/preview_server.h"
#include "io/assemble/load_cache.h"
#include "io/base/file_stamp.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;

// How often the files are looked at, and how long they must stay unchanged before a reload (an
// editor that saves by writing a new file and renaming it makes several changes in a row).
constexpr auto kPollInterval = std::chrono::milliseconds(100);
constexpr auto kSettleTime = std::chrono::milliseconds(40);

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The scene's name as a download's file name: letters, digits, '.', '-' and '_' only.
std::string download_name(const std::string& scene) {
  std::string name = std::filesystem::path(scene).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return name.empty() ? std::string("render") : name;
}

// The session: what was loaded last, the files it read, and how to load it again.
class WatchSession {
 public:
  WatchSession(const WatchCommand& cmd, LoadOptions options, PreviewBoard& board, PreviewRenderer& renderer)
      : cmd_(cmd), options_(std::move(options)), board_(board), renderer_(renderer) {
    options_.cache = &cache_;
  }

  // Loads the scene (again): a good load replaces what renders, a bad one leaves it and shows why.
  void load(Clock::time_point seen, const std::vector<std::string>& changed) {
    const std::string& scene = cmd_.render.scene;
    // Stamped before reading: a save during the load is seen by the next look.
    std::vector<std::string> watched = inputs_.empty() ? std::vector<std::string>{scene} : inputs_;
    const FileStamps before = FileStamps::of(watched);
    Diagnostics diags;
    std::optional<LoadedScene> loaded = load_scene(scene, options_, diags);
    const LoadCache::Counts counts = cache_.take_counts();
    print_diagnostics(stderr, diags);
    std::optional<RenderSettings> settings;
    if (loaded) {
      settings = with_overrides(loaded->settings, cmd_.render);
      if (pixel_count(*settings) > kMaxPixels) {
        diags.file_error(scene, std::to_string(settings->width) + " x " + std::to_string(settings->height) +
                                    " is more pixels than rtcli renders (docs/errors-and-limits.md, \"Limits\")");
        print_diagnostics(stderr, diags);
        loaded.reset();
      }
    }
    if (!loaded) {
      board_.post_failure(diags.all());
      std::fprintf(stderr, "rtcli watch: %s has errors: the page shows the last good image until they are fixed\n",
                   scene.c_str());
      if (inputs_.empty()) inputs_ = {scene};
      stamps_ = before;
      return;
    }
    // What to watch from now on: every file the load read, stamped as they were before it.
    std::set<std::string> seen_paths;
    inputs_.clear();
    for (const std::string& f : loaded->inputs)
      if (seen_paths.insert(f).second) inputs_.push_back(f);
    stamps_ = FileStamps::of(inputs_);
    for (size_t i = 0; i < inputs_.size(); ++i)
      for (size_t j = 0; j < before.paths.size(); ++j)
        if (before.paths[j] == inputs_[i]) stamps_.stamps[i] = before.stamps[j];

    std::string reload;
    char buf[160];
    // Kept: what an earlier load had read from files that did not change (models with their BVHs,
    // textures, environment images); read: those read afresh.
    std::snprintf(buf, sizeof buf, "loaded in %.2f s: %d file%s kept, %d read", seconds_since(seen), counts.kept,
                  counts.kept == 1 ? "" : "s", counts.read);
    reload = buf;
    if (!changed.empty()) {
      reload = std::filesystem::path(changed.front()).filename().string() +
               (changed.size() > 1 ? " and " + std::to_string(changed.size() - 1) + " more" : "") + " changed; " +
               reload;
      std::printf("rtcli watch: %s\n", reload.c_str());
      std::fflush(stdout);
    }
    const Timeline& t = loaded->graph.timeline;
    const bool animated = loaded->graph.animated;
    const uint64_t version = board_.post_load(diags.all(), reload, t.first_frame, t.last_frame, animated);
    int frame = loaded->frame;
    if (first_load_ && cmd_.frame) frame = *cmd_.frame;
    else if (!first_load_ && animated) frame = std::clamp(renderer_.frame(), t.first_frame, t.last_frame);
    first_load_ = false;
    scene_ = std::make_shared<const LoadedScene>(std::move(*loaded));
    renderer_.show(scene_, *settings, version, frame, seen);
  }

  // The files whose stamps changed since the last load (empty: none).
  std::vector<std::string> changed() const { return stamps_.changed(); }
  const std::vector<std::string>& inputs() const { return inputs_; }

  // Whether `frame` can be shown: a frame of the animation, or the one frame of a still scene.
  bool frame_ok(int frame) const {
    const auto s = board_.status();
    return s.animated ? frame >= s.first_frame && frame <= s.last_frame : frame == renderer_.frame();
  }

 private:
  const WatchCommand& cmd_;
  LoadOptions options_;
  PreviewBoard& board_;
  PreviewRenderer& renderer_;
  LoadCache cache_;
  std::shared_ptr<const LoadedScene> scene_;
  std::vector<std::string> inputs_;
  FileStamps stamps_;
  bool first_load_ = true;
};

}  // namespace

int run_watch(const WatchCommand& cmd) {
  const std::optional<Isa> isa = choose_isa(cmd.render.isa, "rtcli watch");
  if (!isa) return kExitBadInput;
  std::optional<LoadOptions> options = scene_load_options(cmd.render, *isa);
  if (!options) return kExitBadInput;
  options->frame = cmd.frame;

  PreviewBoard board(cmd.render.scene);
  PreviewRenderer renderer(board);
  WatchSession session(cmd, *options, board, renderer);
  PreviewServer server(
      board,
      [&](int frame) {
        if (!session.frame_ok(frame)) return false;
        renderer.show_frame(frame);
        return true;
      },
      [&](float yaw, float pitch) { renderer.show_orbit(yaw, pitch); }, download_name(cmd.render.scene));
  std::string error;
  if (!server.bind(cmd.bind, cmd.port, error)) {
    fail(error);
    return kExitFailure;
  }
  const InterruptWatch interrupt;
  server.start();
  const std::string host = cmd.bind.find(':') != std::string::npos ? "[" + cmd.bind + "]" : cmd.bind;
  std::printf("rtcli watch: http://%s:%d/ shows %s as it renders; save the scene to see it again; Ctrl-C stops\n",
              host.c_str(), server.port(), cmd.render.scene.c_str());
  if (cmd.bind != "127.0.0.1" && cmd.bind != "localhost" && cmd.bind != "::1")
    std::fprintf(stderr, "rtcli watch: warning: --bind %s: other machines can see the render\n", cmd.bind.c_str());
  std::fflush(stdout);

  session.load(Clock::now(), {});
  while (!interrupt.flag().load()) {
    std::this_thread::sleep_for(kPollInterval);
    std::vector<std::string> changed = session.changed();
    if (changed.empty()) continue;
    const Clock::time_point seen = Clock::now();
    // Wait until the files stay as they are (a save by rename is a delete and a create).
    FileStamps last = FileStamps::of(session.inputs());
    for (int i = 0; i < 50 && !interrupt.flag().load(); ++i) {
      std::this_thread::sleep_for(kSettleTime);
      FileStamps now = FileStamps::of(session.inputs());
      if (now.stamps == last.stamps) break;
      last = std::move(now);
    }
    session.load(seen, changed);
  }
  server.stop();
  std::printf("rtcli watch: stopped\n");
  return kExitSuccess;
}

}  // namespace rt
