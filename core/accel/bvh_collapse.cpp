#include "core/accel/bvh_binary_tree.h"
#include "core/parallel_for.h"

namespace rt {
namespace {

void set_child(BvhNode& node, int slot, const Aabb& box, uint32_t ref) {
  node.bounds[0][slot] = box.lo.x;
  node.bounds[1][slot] = box.hi.x;
  node.bounds[2][slot] = box.lo.y;
  node.bounds[3][slot] = box.hi.y;
  node.bounds[4][slot] = box.lo.z;
  node.bounds[5][slot] = box.hi.z;
  node.child[slot] = ref;
}

// The binary nodes interior node `b` adopts as its wide node's children; returns how many.
int adopt(const std::vector<BinaryNode>& bin, uint32_t b, uint32_t (&kids)[kBvhWidth]) {
  kids[0] = b + 1;
  kids[1] = bin[b].offset;
  int k = 2;
  while (k < kBvhWidth) {
    int widest = -1;
    double widest_area = -1.0;
    for (int i = 0; i < k; ++i) {
      const BinaryNode& c = bin[kids[i]];
      if (c.count == 0 && half_area(c.bounds) > widest_area) {
        widest = i;
        widest_area = half_area(c.bounds);
      }
    }
    if (widest < 0) break;
    const uint32_t opened = kids[widest];
    kids[widest] = opened + 1;
    kids[k++] = bin[opened].offset;
  }
  return k;
}

// The wide node for binary node `b`, its children's references from child_ref(slot, kid).
template <class ChildRef>
BvhNode wide_node(const std::vector<BinaryNode>& bin, const uint32_t (&kids)[kBvhWidth], int k,
                  const ChildRef& child_ref) {
  BvhNode node{};  // padding zeroed too: the tree's bytes are as deterministic as its shape
  for (int slot = 0; slot < kBvhWidth; ++slot) {
    if (slot < k) set_child(node, slot, bin[kids[slot]].bounds, child_ref(slot, kids[slot]));
    else set_child(node, slot, Aabb{}, 0);  // inverted box: never entered
  }
  return node;
}

uint32_t collapse(const std::vector<BinaryNode>& bin, uint32_t b, std::vector<BvhNode>& out) {
  const BinaryNode& n = bin[b];
  if (n.count > 0) return BvhRef::leaf(n.offset, n.count);
  uint32_t kids[kBvhWidth];
  const int k = adopt(bin, b, kids);
  const auto index = static_cast<uint32_t>(out.size());
  out.emplace_back();
  out[index] = wide_node(bin, kids, k, [&](int, uint32_t kid) { return collapse(bin, kid, out); });
  return index;
}

}  // namespace

uint32_t collapse_binary_tree(const std::vector<BinaryNode>& bin, unsigned threads, std::vector<BvhNode>& out) {
  const BinaryNode& root = bin[0];
  if (root.count > 0) return BvhRef::leaf(root.offset, root.count);
  uint32_t kids[kBvhWidth];
  const int k = adopt(bin, 0, kids);
  // Each child's subtree in its own array (the collapse took 5% of a 2-thread build on one thread).
  std::vector<BvhNode> subtree[kBvhWidth];
  uint32_t ref[kBvhWidth];
  parallel_for(static_cast<size_t>(k), threads, 1, [&](unsigned, size_t slot) {
    subtree[slot].reserve(bin.size() / kBvhWidth / k + 1);
    ref[slot] = collapse(bin, kids[slot], subtree[slot]);
  });
  const auto index = static_cast<uint32_t>(out.size());
  out.emplace_back();
  out[index] = wide_node(bin, kids, k, [&](int slot, uint32_t) {
    const auto base = static_cast<uint32_t>(out.size());
    // Links inside the subtree rebased to where it lands (leaves refer to slots, not nodes; an
    // unused slot's inverted box keeps its 0).
    for (BvhNode node : subtree[slot]) {
      for (int s = 0; s < kBvhWidth; ++s)
        if (child_used(node, s) && !BvhRef::is_leaf(node.child[s])) node.child[s] += base;
      out.push_back(node);
    }
    return BvhRef::is_leaf(ref[slot]) ? ref[slot] : ref[slot] + base;
  });
  return index;
}

}  // namespace rt
