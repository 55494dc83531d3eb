// What `rtcli bench` and tools/embree_compare trace: a model's triangles and shapes placed in
// the world, or a generated mesh.
#pragma once

#include <optional>
#include <string>

#include "core/accel/primitives.h"
#include "io/base/diagnostics.h"

namespace rt {

struct BenchModel {
  PrimitiveSet prims;
  std::string name;  // the file, or what was generated
};

// `path` (.gltf/.glb/.json) loaded and flattened; an empty path generates a displaced sphere of
// 301,400 triangles (cli/bench/generated_mesh.h). nullopt when the file does not load (`diags`
// says why).
std::optional<BenchModel> load_bench_model(const std::string& path, Diagnostics& diags);

}  // namespace rt
