// Bvh::check_structure, the invariants traversal relies on checked the slow, obvious way; and
// Bvh::stats, what the tree looks like (nodes, leaves, depth).
#include <vector>

#include "core/accel/bvh.h"

namespace rt {
namespace {

bool contains(const Aabb& outer, const Aabb& inner) {
  return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z && inner.hi.x <= outer.hi.x &&
         inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
}

Aabb child_box(const BvhNode& node, int slot) {
  return Aabb{Vec3(node.bounds[0][slot], node.bounds[2][slot], node.bounds[4][slot]),
              Vec3(node.bounds[1][slot], node.bounds[3][slot], node.bounds[5][slot])};
}

}  // namespace

std::string Bvh::check_structure() const {
  const uint32_t n = primitive_count();
  if (n == 0) return nodes_.empty() ? "" : "nodes without primitives";
  std::vector<int> seen(n, 0);
  size_t used_slots = 0;
  std::vector<bool> visited(nodes_.size(), false);
  struct Item {
    uint32_t ref;
    Aabb box;  // the box the parent holds for this entry
    int depth;
  };
  std::vector<Item> stack{{root_, bounds_, 0}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.depth > kMaxDepth) return "deeper than kMaxDepth";
    if (BvhRef::is_quad_leaf(item.ref)) {
      const uint32_t first = BvhRef::first(item.ref), count = BvhRef::count(item.ref);
      if (count == 0 || first + BvhRef::quad_count(item.ref) > quads_.size()) return "quad leaf outside the quad array";
      for (uint32_t k = 0; k < 4 * BvhRef::quad_count(item.ref); ++k) {
        const TriangleQuad& quad = quads_[first + k / 4];
        const int lane = static_cast<int>(k % 4);
        if (k >= count) {
          if (quad.id[lane] != ~0u) return "a quad's unused lane holds a primitive";
          continue;
        }
        const uint32_t id = quad.id[lane];
        if (kind(id) != PrimitiveKind::kTriangle) return "quad lane " + std::to_string(k) + " holds a non-triangle id";
        if (++seen[id] > 1) return "primitive " + std::to_string(id) + " is in two leaves";
        if (!contains(item.box, quad_lane(quad, lane).bounds()))
          return "primitive " + std::to_string(id) + " sticks out of its leaf's box";
      }
      continue;
    }
    if (BvhRef::is_leaf(item.ref)) {
      const uint32_t first = BvhRef::first(item.ref), count = BvhRef::count(item.ref);
      if (count == 0 || first + count > slots_.size()) return "leaf outside the slot array";
      used_slots += count;
      for (uint32_t slot = first; slot < first + count; ++slot) {
        const uint32_t id = slots_[slot].id;
        if (id >= n) return "slot " + std::to_string(slot) + " holds an invalid id";
        if (++seen[id] > 1) return "primitive " + std::to_string(id) + " is in two leaves";
        const Aabb box = primitive_bounds(id, slots_[slot]);
        if (!contains(item.box, box)) return "primitive " + std::to_string(id) + " sticks out of its leaf's box";
      }
      continue;
    }
    if (item.ref >= nodes_.size())
      return "reference to node " + std::to_string(item.ref) + " of " + std::to_string(nodes_.size());
    if (visited[item.ref]) return "node " + std::to_string(item.ref) + " is reached twice";
    visited[item.ref] = true;
    const BvhNode& node = nodes_[item.ref];
    int children = 0;
    for (int slot = 0; slot < kBvhWidth; ++slot) {
      const Aabb box = child_box(node, slot);
      if (box.empty()) continue;  // an unused slot
      ++children;
      if (!contains(item.box, box)) return "a child box of node " + std::to_string(item.ref) + " sticks out";
      stack.push_back(Item{node.child[slot], box, item.depth + 1});
    }
    if (children < 2) return "node " + std::to_string(item.ref) + " has fewer than two children";
  }
  for (uint32_t id = 0; id < n; ++id) {
    // A flattened instance is in no leaf: its triangles are, in its place.
    const bool flattened = kind(id) == PrimitiveKind::kInstance && instance(id).flattened;
    if (flattened && seen[id] != 0) return "flattened instance " + std::to_string(id) + " is in a leaf";
    if (!flattened && seen[id] != 1) return "primitive " + std::to_string(id) + " is in no leaf";
  }
  if (!owners_.empty() && owners_.size() != triangle_count()) return "not one owner a triangle";
  for (const TriangleOwner& o : owners_)
    if (o.instance >= instances_.size() || !instances_[o.instance].flattened)
      return "a triangle owned by an instance that is not flattened";
  if (used_slots != slots_.size()) return "slots that no leaf refers to";
  return "";
}

BvhStats Bvh::stats() const {
  BvhStats s;
  s.nodes = nodes_.size();
  s.sah_cost = binary_sah_cost_;
  if (primitive_count() == 0) return s;
  struct Item {
    uint32_t ref;
    int depth;
  };
  std::vector<Item> stack{{root_, 0}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    s.max_depth = std::max(s.max_depth, it.depth);
    if (BvhRef::is_leaf(it.ref)) {
      ++s.leaves;
      continue;
    }
    const BvhNode& node = nodes_[it.ref];
    for (int slot = 0; slot < kBvhWidth; ++slot)
      if (child_used(node, slot)) stack.push_back({node.child[slot], it.depth + 1});
  }
  return s;
}

}  // namespace rt
