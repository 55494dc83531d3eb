// `rtcli render SCENE [-o OUT.png] [--threads N] [--width W] [--height H] [--seed S]
//   [--integrator NAME] [--glossy-samples N] [--no-glossy] [--shadow-samples N] [--quiet]`
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace rt {

struct RenderCommand {
  std::string scene;
  std::string output;  // empty: <scene name>.png in the current folder
  std::optional<unsigned> threads;
  std::optional<int> width, height;
  std::optional<uint64_t> seed;
  std::optional<std::string> integrator;
  std::optional<int> glossy_samples;
  std::optional<int> shadow_samples;
  bool no_glossy = false;
  bool quiet = false;
};

int run_render(const RenderCommand& cmd);

}  // namespace rt
