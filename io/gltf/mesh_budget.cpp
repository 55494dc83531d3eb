#include "io/gltf/mesh_budget.h"

#include <algorithm>

#include <tiny_gltf.h>

#include "io/gltf/accessor.h"

namespace rt {

using std::to_string;

MeshCost primitive_cost(const tinygltf::Model& model, const tinygltf::Primitive& prim) {
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  const auto pos = prim.attributes.find("POSITION");
  if (pos == prim.attributes.end() ||
      (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN))
    return {};
  const uint64_t vertices = accessor_count(model, pos->second);
  const uint64_t indices = prim.indices >= 0 ? accessor_count(model, prim.indices) : vertices;
  return {vertices, mode == TINYGLTF_MODE_TRIANGLES ? indices / 3 : (indices >= 2 ? indices - 2 : 0)};
}

std::vector<bool> meshes_used(const tinygltf::Model& model, const std::optional<std::string>& mesh_name, int scene) {
  std::vector<bool> used(model.meshes.size(), false);
  if (mesh_name) {
    for (size_t i = 0; i < model.meshes.size(); ++i)
      if (model.meshes[i].name == *mesh_name) {
        used[i] = true;
        break;
      }
    return used;
  }
  if (scene < 0 || static_cast<size_t>(scene) >= model.scenes.size()) {
    used.assign(used.size(), true);
    return used;
  }
  std::vector<bool> seen(model.nodes.size(), false);
  std::vector<int> stack(model.scenes[static_cast<size_t>(scene)].nodes);
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    if (n < 0 || static_cast<size_t>(n) >= seen.size() || seen[static_cast<size_t>(n)]) continue;
    seen[static_cast<size_t>(n)] = true;
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(n)];
    if (node.mesh >= 0 && static_cast<size_t>(node.mesh) < used.size()) used[static_cast<size_t>(node.mesh)] = true;
    stack.insert(stack.end(), node.children.begin(), node.children.end());
  }
  return used;
}

bool meshes_fit(const tinygltf::Model& model, const std::vector<bool>& used, const LoadLimits& limits,
                const LimitUsage& usage, Reporter& report) {
  MeshCost total;
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    if (!used[m]) continue;
    for (const tinygltf::Primitive& prim : model.meshes[m].primitives) {
      const MeshCost c = primitive_cost(model, prim);
      total.vertices += std::min<uint64_t>(c.vertices, uint64_t{1} << 40);  // no wrap, whatever the counts
      total.triangles += std::min<uint64_t>(c.triangles, uint64_t{1} << 40);
    }
  }
  const auto over = [&](const char* what, uint64_t limit, uint64_t taken, uint64_t wanted) {
    report.over_limit("/meshes",
                      "expected at most " + to_string(limit) + " " + what + " in a scene's meshes, found " +
                          to_string(wanted) + " in this file's (counted from their accessors, before reading them)" +
                          (taken ? " after " + to_string(taken) + " in the meshes before it" : std::string()));
    return false;
  };
  if (total.vertices + usage.vertices > limits.vertices)
    return over("vertices", limits.vertices, usage.vertices, total.vertices);
  if (total.triangles + usage.triangles > limits.triangles)
    return over("triangles", limits.triangles, usage.triangles, total.triangles);
  return true;
}

}  // namespace rt
