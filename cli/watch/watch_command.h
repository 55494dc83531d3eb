// `rtcli watch SCENE [--port N] [--bind ADDRESS] [--frame N] [render's scene options]`: a local
// page that shows the scene's render refining (cli/watch/preview_renderer.h), loaded again
// whenever the scene or a file it reads is saved, only what changed read again
// (io/assemble/load_cache.h). A scene with errors shows them, located, beside the last good
// image. Ctrl-C stops the server and the render. Exit codes: 0 after Ctrl-C, 2 for bad options,
// 1 when the address cannot be served.
#pragma once

#include <optional>
#include <string>

#include "cli/render/render_command.h"

namespace rt {

struct WatchCommand {
  RenderCommand render;  // the scene and the options that choose how it renders
  int port = 8765;
  std::string bind = "127.0.0.1";
  std::optional<int> frame;  // of the scene's animation (default: its first)
};

int run_watch(const WatchCommand& cmd);

}  // namespace rt
