// A test scene the path tracer's tests share.
#pragma once

namespace rt::test {

// A glossy floor lit by a small bright and a large dim rect light (Veach's scene, simplified):
// light sampling is poor at the large light's reflection, BSDF sampling at the small light's.
inline constexpr const char* kTwoLights = R"({
  "render": { "width": 16, "height": 12, "integrator": "path", "samples_per_pixel": 32, "max_depth": 1, "seed": 9 },
  "camera": { "position": [0, 2, 5], "look_at": [0, 0, 0], "fov": 50 },
  "background": [0, 0, 0],
  "materials": { "floor": { "kd": 0.3, "ks": 0.6, "shininess": 60 } },
  "lights": [
    { "type": "rect", "corner": [-1.6, 2, -1.15], "edge1": [0.25, 0, 0], "edge2": [0, 0, 0.25], "color": [64, 64, 64] },
    { "type": "rect", "corner": [0.2, 2.5, -2], "edge1": [2.5, 0, 0], "edge2": [0, 0, 2.5], "color": [1.5, 1.5, 1.5] }
  ],
  "nodes": [ { "name": "floor", "shape": "plane", "material": "floor", "transform": { "scale": 4 } } ]
})";

}  // namespace rt::test
