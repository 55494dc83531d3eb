// A glTF model rendered on its own (`rtcli render model.glb`): the camera that frames it and the
// light that shows its form, added to its scene graph by the builder (io/assemble/scene_builder.cpp).
#pragma once

#include <optional>
#include <string>

#include "core/accel/primitives.h"
#include "core/scene_graph.h"

namespace rt {

// Frames the model from the front and above, over its whole animation (so that nothing moving
// leaves the image), and puts a point light up and to the right of the camera in use, so that
// shading shows the form and shadows fall behind (unless the model has lights of its own).
// `placed`: the model at its first frame. The camera: unless `keep_camera` (--camera chose one
// already), `file_camera` (the model's first camera) or else the framing one. Fails, with `error`
// saying why, for a model too large to frame in single precision.
bool frame_model(SceneGraph& g, const PrimitiveSet& placed, float aspect, bool keep_camera,
                 const std::optional<CameraPlacement>& file_camera, std::string& error);

}  // namespace rt
