#include "cli/bench/bench_model.h"

#include "cli/bench/generated_mesh.h"
#include "cli/common/scene_loading.h"
#include "io/scene_loader.h"

namespace rt {

std::optional<BenchModel> load_bench_model(const std::string& path, Diagnostics& diags) {
  if (path.empty())
    return BenchModel{make_primitive_set({make_benchmark_mesh(300'000)}, {}), "generated displaced sphere"};
  const auto loaded = load_scene(path, cli_load_options(), diags);
  if (!loaded) return std::nullopt;
  return BenchModel{make_primitive_set(loaded->scene.world_meshes(), loaded->scene.bvh.shapes()), path};
}

}  // namespace rt
