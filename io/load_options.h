// What the caller tells the loaders: threads for the BVH build, and the names the render
// pipeline offers (io does not link the renderer; cli passes integrator_names()).
#pragma once

#include <string>
#include <vector>

namespace rt {

struct LoadOptions {
  unsigned threads = 0;                              // for the BVH build; 0 = all hardware threads
  std::vector<std::string> integrators{"whitted"};  // valid values of /render/integrator
};

}  // namespace rt
