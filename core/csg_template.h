// A CSG solid as the scene graph keeps it between frames: its tree in prefix order over scene
// nodes. Each frame, place_csg() builds the CsgObject the BVH holds, with every operand where its
// node's world transform puts it then (so tracks can move operands, and the solid with them).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/csg/csg_object.h"
#include "core/math.h"
#include "core/scene_assets.h"

namespace rt {

// One mesh primitive of an operand, placed by scene node `node`.
struct CsgMeshPart {
  uint32_t node = 0;
  uint32_t mesh = 0;  // index into SceneAssets::meshes
  uint32_t material = 0;
};

struct CsgTemplateNode {
  bool leaf = false;
  CsgOp op = CsgOp::kUnion;
  uint32_t end = 0;   // one past this subtree
  uint32_t node = 0;  // the scene node that carries it
  // A leaf: a shape placed by `node`, or the mesh primitives of `node` and the nodes a glTF
  // file grafted under it.
  std::optional<ShapeKind> shape;
  uint32_t material = 0;
  std::vector<CsgMeshPart> meshes;
};

struct CsgTemplate {
  std::vector<CsgTemplateNode> nodes;  // nodes[0]: the root operation
  uint32_t root_node() const { return nodes.front().node; }
};

// Why a solid could not be placed: an operand's world transform is singular or reaches beyond
// the float range (which node), or it encloses nothing (an intersection of operands that do not
// meet: not an error, it just draws nothing).
struct CsgPlacement {
  std::optional<CsgObject> object;
  std::optional<uint32_t> singular_node, beyond_range_node;
};

CsgPlacement place_csg(const CsgTemplate& t, const std::vector<Mat4>& world, const SceneAssets& assets);

// Edges of the mesh used by an odd number of its triangles, vertices joined by position (so
// that seams where UVs or normals split a vertex do not count): 0 for a closed surface.
size_t count_open_edges(const std::vector<const TriangleMesh*>& parts);

}  // namespace rt
