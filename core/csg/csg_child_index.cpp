#include "core/csg/csg_child_index.h"

#include <algorithm>
#include <cmath>

namespace rt {

CsgReach CsgReach::whole(const Ray& ray) {
  CsgReach reach;
  reach.line = ray;
  reach.line.tmin = -kInfinity;
  reach.line.tmax = kInfinity;
  return reach;
}

CsgReach CsgReach::of(const Ray& ray) {
  CsgReach reach = whole(ray);
  // A thousandth of the distances involved: the origin's size in units of the direction (what a
  // distance's rounding scales with) and the interval's own ends.
  const float direction =
      std::max({std::fabs(ray.direction.x), std::fabs(ray.direction.y), std::fabs(ray.direction.z)});
  const float origin = std::max({std::fabs(ray.origin.x), std::fabs(ray.origin.y), std::fabs(ray.origin.z)});
  if (!(direction > 0.0f)) return reach;
  const float finite_hi = std::isfinite(ray.tmax) ? std::fabs(ray.tmax) : 0.0f;
  const float slack = 1e-3f * ((origin + 1.0f) / direction + std::fabs(ray.tmin) + finite_hi);
  if (!(slack >= 0.0f)) return reach;  // a NaN: the whole line
  reach.lo = ray.tmin - slack;
  reach.hi = ray.tmax + slack;  // an infinite tmax stays infinite
  return reach;
}

CsgChildIndex::CsgChildIndex(const std::vector<uint32_t>& children, const std::vector<Aabb>& bounds) {
  items_.reserve(children.size());
  for (size_t i = 0; i < children.size(); ++i) items_.push_back(Item{children[i], bounds[i]});
  boxes_.reserve(2 * (children.size() / kLeafSize + 1));
  boxes_.emplace_back();
  build(0, 0, static_cast<uint32_t>(items_.size()), 0);
}

// Median splits on the widest axis of the boxes' centres: a balanced tree, whatever the layout.
void CsgChildIndex::build(uint32_t box, uint32_t begin, uint32_t end, int depth) {
  Aabb bounds, centres;
  for (uint32_t i = begin; i < end; ++i) {
    bounds.extend(items_[i].bounds);
    if (!items_[i].bounds.empty()) centres.extend(items_[i].bounds.centre());
  }
  boxes_[box].bounds = bounds;
  if (end - begin <= kLeafSize || depth >= kMaxDepth || centres.empty()) {
    boxes_[box].first = begin;
    boxes_[box].count = end - begin;
    return;
  }
  const int axis = centres.largest_axis();
  const uint32_t mid = begin + (end - begin) / 2;
  // Ties broken by the child's index: the same tree on every machine.
  std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                   [&](const Item& a, const Item& b) {
                     const float ca = a.bounds.empty() ? 0.0f : a.bounds.centre()[axis],
                                 cb = b.bounds.empty() ? 0.0f : b.bounds.centre()[axis];
                     return ca < cb || (ca == cb && a.child < b.child);
                   });
  const uint32_t left = static_cast<uint32_t>(boxes_.size());
  boxes_.emplace_back();
  boxes_.emplace_back();
  boxes_[box].first = left;
  boxes_[box].count = 0;
  build(left, begin, mid, depth + 1);
  build(left + 1, mid, end, depth + 1);
}

int CsgChildIndex::met(const CsgReach& reach, uint32_t* out, int capacity) const {
  uint32_t stack[kMaxDepth + 2];
  int top = 0, found = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Box& b = boxes_[stack[--top]];
    if (!reach_meets_box(b.bounds, reach)) continue;
    if (b.count == 0) {
      stack[top++] = b.first;
      stack[top++] = b.first + 1;
      continue;
    }
    for (uint32_t i = b.first; i < b.first + b.count; ++i) {
      if (!reach_meets_box(items_[i].bounds, reach)) continue;
      if (found == capacity) return -1;
      out[found++] = items_[i].child;
    }
  }
  std::sort(out, out + found);
  return found;
}

}  // namespace rt
