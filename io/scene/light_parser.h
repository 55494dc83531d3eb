// The "lights" array of a scene file: point, rect, spot and directional lights, each checked
// (a rectangle's edges span an area, a spot's outer cone is wider than its inner one).
#pragma once

#include <string>
#include <vector>

#include "core/lights/light.h"
#include "io/json/reader.h"

namespace rt {

// A file's lights, after those of earlier files; `pointers` gets each one's.
void parse_lights(const JsonReader& r, const Json& v, const std::string& ptr, std::vector<Light>& out,
                  std::vector<std::string>& pointers);

}  // namespace rt
