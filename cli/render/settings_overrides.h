// The scene's render settings with the command line's overrides applied (render and watch).
// The option values were checked as they were parsed; names are looked up here.
#pragma once

#include <optional>

#include "cli/render/render_command.h"
#include "core/render_settings.h"
#include "io/base/load_options.h"

namespace rt {

RenderSettings with_overrides(RenderSettings s, const RenderCommand& cmd);

// How the command asks io for the scene: threads, the instruction set, a glTF camera, outside
// files, the animation and frame rate of a model alone, the integrator, and the background,
// ambient light and environment image that replace the scene's. Nothing, after saying why
// (exit 2), for options that do not go together.
std::optional<LoadOptions> scene_load_options(const RenderCommand& cmd, Isa isa);

}  // namespace rt
