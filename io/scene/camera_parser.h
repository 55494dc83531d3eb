// The "camera" object of a scene file: where it is, its projection, lens and stereo settings.
#pragma once

#include "io/json/reader.h"
#include "io/scene/description.h"

namespace rt {

void parse_camera(const JsonReader& r, const Json& value, const std::string& pointer, CameraDescription& camera);

// The camera a description asks for, its defaults filled in: focus at the look-at point,
// convergence at the focus.
Camera make_camera(const CameraDescription& description);

}  // namespace rt
