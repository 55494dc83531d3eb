// rtcli:settings (cli/frames/render_metadata.h): every setting that shapes the pixels, as text,
// for telling renders apart: the render settings and the command's choices that change the pixels
// but are not render settings (camera, background, ambient, animation, fps, stereo). Not threads,
// tile size, outputs or the part rendered.
#pragma once

#include <string>

#include "cli/render/render_job.h"
#include "core/render_settings.h"
#include "core/stereo.h"

namespace rt {

std::string settings_text(const RenderSettings& settings, const PixelChoices& choices, StereoMode stereo);

}  // namespace rt
