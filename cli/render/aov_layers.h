// The layers an EXR output may hold beside the colour (--aov): each one's name, the integrator
// that renders its data, its channels, and whether it is one ray through the pixel's centre.
// Albedo and normal are averaged as the colour is (what denoisers expect); the depth is one ray,
// as Blender's Z pass, since an average of a near surface and the background's 1e10 is no
// distance at all.
#pragma once

#include <string>
#include <vector>

namespace rt {

struct AovLayer {
  const char* name;
  const char* integrator;
  std::vector<std::string> channels;
  bool one_ray;
};

inline const std::vector<AovLayer>& aov_layers() {
  static const std::vector<AovLayer> layers = {{"albedo", "albedo", {"R", "G", "B"}, false},
                                               {"normal", "aov-normal", {"X", "Y", "Z"}, false},
                                               {"depth", "aov-depth", {"Z"}, true}};
  return layers;
}

// The layer called `name`, or null.
inline const AovLayer* find_aov(const std::string& name) {
  for (const AovLayer& l : aov_layers())
    if (name == l.name) return &l;
  return nullptr;
}

}  // namespace rt
