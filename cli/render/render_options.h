// The options of `rtcli render` (cli/render/render_command.h), declared once: those that choose
// how a scene is rendered (its settings' overrides, the camera, the files it may read), which
// `rtcli watch` takes too, and those about the outputs and shares of a render, which only render
// takes.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/render/render_command.h"

namespace rt {

// What --allow-outside-files and --isa say, for every command that takes them.
extern const char* const kOutsideFilesHelp;
std::string isa_help();

// The settings' overrides, --threads, --isa, --camera, --animation, --fps, --background, --ambient
// and --allow-outside-files.
void add_scene_options(CLI::App& cmd, RenderCommand& r);
// Those, the scene file, and render's own: outputs, frames, shares, layers, denoising, --stats.
void add_render_options(CLI::App& cmd, RenderCommand& r);

}  // namespace rt
