// `rtcli bench [MODEL] [--scene SCENE.json]`: BVH build time and ray throughput on a mesh, for one
// thread and for all threads, then the render time of the primitives scene.
#pragma once

#include <string>

namespace rt {

struct BenchCommand {
  std::string model;  // .gltf/.glb/.json; empty = a generated mesh of 300k+ triangles
  std::string scene;  // rendered at the end; empty = none
};

int run_bench(const BenchCommand& cmd);

}  // namespace rt
