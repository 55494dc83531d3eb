// What the builder says about a scene that renders, but not as its author likely meant: nothing
// to render, nothing to light it, a light that reaches no geometry (a rect light facing away, a
// spot light aimed past everything), a camera that starts inside a closed shape. Warnings only,
// so the same in `render` and `validate`, at the JSON pointer of the light or node concerned.
#pragma once

#include <string>
#include <vector>

#include "core/aabb.h"
#include "core/accel/primitives.h"
#include "core/scene.h"
#include "core/scene_graph.h"
#include "io/base/reporter.h"

namespace rt {

// Whether a light sends any light into `box` (conservatively: true when unsure).
bool light_can_reach(const Light& light, const Aabb& box);

// Whether `point` lies strictly inside the closed analytic shape of `kind` placed by `to_world`
// (the plane is no solid: never).
bool inside_shape(ShapeKind kind, const Mat4& to_world, Vec3 point);

// The world bounds of what a frame places: each shape and mesh instance, the loose triangles as
// one box.
std::vector<Aabb> geometry_bounds(const PrimitiveSet& placed);

// `geometry`: the world bounds of what the frame places (each shape and mesh instance; the loose
// triangles as one box). `light_pointers`: per scene.lights entry, where it is described (empty
// for the light rtcli adds to a model on its own, which is never warned about).
// `path_traced`: the scene asks for the path tracer, which its background lights.
void warn_unlit_or_empty(const Scene& scene, bool path_traced, const std::vector<Aabb>& geometry,
                         const std::vector<std::string>& light_pointers, Reporter& report);

// pointers: per node, where the scene describes it.
void warn_camera_inside(const SceneGraph& g, const Pose& pose, Vec3 camera, const std::vector<std::string>& pointers,
                        Reporter& report);

}  // namespace rt
