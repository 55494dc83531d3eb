// The scene's render settings with the command line's overrides applied (render and watch).
// The option values were checked as they were parsed; names are looked up here.
#pragma once

#include "cli/render/render_command.h"
#include "core/render_settings.h"

namespace rt {

RenderSettings with_overrides(RenderSettings s, const RenderCommand& cmd);

}  // namespace rt
