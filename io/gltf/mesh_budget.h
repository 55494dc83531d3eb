// What a glTF file's meshes will take of the scene's vertex and triangle limits, from their
// accessors' counts alone: checked before any accessor is read, so that many primitives sharing
// one huge accessor are refused at once rather than read one by one until the limit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/base/load_options.h"
#include "io/base/reporter.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace rt {

struct MeshCost {
  uint64_t vertices = 0, triangles = 0;
};

// What a primitive will take (nothing for points and lines, which are skipped).
MeshCost primitive_cost(const tinygltf::Model& model, const tinygltf::Primitive& prim);

// The meshes an import will read, each once: the one asked for by name, those the default
// scene's nodes use (`scene` < 0: the file has none, so all of them).
std::vector<bool> meshes_used(const tinygltf::Model& model, const std::optional<std::string>& mesh_name, int scene);

// Whether the used meshes fit in what `usage` leaves of `limits`; if not, reported (over_limit).
bool meshes_fit(const tinygltf::Model& model, const std::vector<bool>& used, const LoadLimits& limits,
                const LimitUsage& usage, Reporter& report);

}  // namespace rt
