#include <cassert>

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

// The wide nodes collapse() makes of the subtree under binary node `b`: none for a leaf.
uint32_t count_wide(const std::vector<BinaryNode>& bin, uint32_t b) {
  if (bin[b].count > 0) return 0;
  uint32_t kids[kBvhWidth];
  const int k = adopt(bin, b, kids);
  uint32_t count = 1;
  for (int i = 0; i < k; ++i) count += count_wide(bin, kids[i]);
  return count;
}

// The subtree under binary node `b` written from out[next] on, a node before its children's
// subtrees in slot order; `next` ends past its last node. Returns the subtree's reference.
uint32_t collapse(const std::vector<BinaryNode>& bin, uint32_t b, BvhNode* out, uint32_t& next) {
  const BinaryNode& n = bin[b];
  if (n.count > 0) return BvhRef::leaf(n.offset, n.count);
  uint32_t kids[kBvhWidth];
  const int k = adopt(bin, b, kids);
  const uint32_t index = next++;
  out[index] = wide_node(bin, kids, k, [&](int, uint32_t kid) { return collapse(bin, kid, out, next); });
  return index;
}

}  // namespace

uint32_t collapse_binary_tree(const std::vector<BinaryNode>& bin, unsigned threads, FillVector<BvhNode>& out) {
  const BinaryNode& root = bin[0];
  if (root.count > 0) return BvhRef::leaf(root.offset, root.count);
  uint32_t kids[kBvhWidth];
  const int k = adopt(bin, 0, kids);
  // Each child's subtree on its own thread, written in place: its nodes counted first, so that
  // every subtree knows where it starts. (Built apart and appended, the copy took 2% of a build
  // on one thread, and the page faults of a second array.)
  uint32_t size[kBvhWidth], first[kBvhWidth], ref[kBvhWidth];
  parallel_for(static_cast<size_t>(k), threads, 1,
               [&](unsigned, size_t slot) { size[slot] = count_wide(bin, kids[slot]); });
  const auto index = static_cast<uint32_t>(out.size());
  uint32_t next = index + 1;
  for (int slot = 0; slot < k; ++slot) {
    first[slot] = next;
    next += size[slot];
  }
  out.resize(next);  // not written here (FillVector): each node by the thread that collapses it
  parallel_for(static_cast<size_t>(k), threads, 1, [&](unsigned, size_t slot) {
    uint32_t at = first[slot];
    ref[slot] = collapse(bin, kids[slot], out.data(), at);
    assert(at == first[slot] + size[slot]);
  });
  out[index] = wide_node(bin, kids, k, [&](int slot, uint32_t) { return ref[slot]; });
  return index;
}

}  // namespace rt
