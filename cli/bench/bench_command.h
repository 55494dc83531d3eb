// `rtcli bench [MODEL] [--scene SCENE.json] [--path-scene SCENE.json] [--repeats N] [--rays FILE]
//   [--save-rays FILE] [--isa sse|avx2|avx512|auto] [--against povray|cycles]...`: BVH
// build time (cold and warm) and ray throughput on a mesh, for one thread and for all threads,
// on rays made before the clock starts; then the render time of a scene, and of a path-traced
// scene (at most 160 pixels a side, 16 samples per pixel) with its samples per second. Every figure is the
// median of N runs after a warm-up, with the fastest and slowest beside it. --against then runs the
// source tree's comparisons with this rtcli: POV-Ray on the scene's twin (tools/povray/compare.py),
// Cycles' samples per second on the path-traced scene's (tools/cycles/speed.py).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt {

struct BenchCommand {
  std::string model;                 // .gltf/.glb/.json; empty = a generated mesh of 300k+ triangles
  std::string scene;                 // rendered at the end; empty = none
  std::string path_scene;            // path traced after it, small; empty = none
  int repeats = 5;                   // timed runs of each figure, after one warm-up
  std::string rays;                  // replay these ray sets instead of generating them
  std::string save_rays;             // write the ray sets traced here, for another build or Embree to replay
  std::optional<std::string> isa;    // --isa: the BVH kernels measured (cli/common/isa_choice.h)
  std::vector<std::string> against;  // "povray", "cycles": the comparisons run last
  std::string tools_dir;             // where they are: the source tree's tools/
};

int run_bench(const BenchCommand& cmd);

}  // namespace rt
