// Constructive solid geometry by span lists along a ray (Roth, "Ray casting for modeling
// solids", 1982): each operand gives the stretches of the ray's line that lie inside it, and an
// operation combines two lists into one. The result's first span boundary past the ray's start is
// the hit. A boundary remembers which operand surface it lies on, so the hit keeps that
// operand's normal, UVs, tangents and material.
//
// Lists come in two forms. A *normal* list is sorted and its spans are disjoint: what merge,
// intersection and difference produce from normal lists. `union` keeps every operand's spans as
// they are (overlaps and all, sorted by entry): its inner walls stay visible, as in POV-Ray's
// union; `merge` is the boolean union, whose inner walls vanish. An operation treats a list with
// overlaps as the set of its spans: intersection and difference cut each span on its own, so the
// inner walls of a union inside stay walls. Fixed capacity, no allocation: a list that would grow
// past it keeps its nearest spans and says so (docs/csg.md).
#pragma once

#include <algorithm>
#include <cstdint>

namespace rt {

enum class CsgOp : uint8_t { kUnion, kMerge, kIntersection, kDifference };

// Where the line crosses one operand surface: its distance, which surface of the CSG object
// (CsgObject::surfaces), and the surface's own hit record (a shape's face, a triangle and its
// barycentrics).
// No default member values, here and in CsgSpan: a list's storage is left unset until a span is
// added, as zeroing 32 spans at every CSG node a ray meets cost more than combining them.
struct CsgBoundary {
  float t;
  uint32_t surface;
  uint32_t part;
  float b1, b2;
};

// One stretch inside the solid, from `in` to `out` (in.t < out.t). `medium`: the material of the
// operand whose inside this is (the first operand of an intersection or difference), which
// refraction takes as the medium behind either boundary.
struct CsgSpan {
  CsgBoundary in, out;
  uint32_t medium;
};

class CsgSpanList {
 public:
  static constexpr int kCapacity = 32;

  CsgSpanList() = default;
  // Copies the spans held, not the whole capacity (lists are copied as a tree is combined).
  CsgSpanList(const CsgSpanList& other) { *this = other; }
  CsgSpanList& operator=(const CsgSpanList& other) {
    count_ = other.count_;
    truncated_ = other.truncated_;
    std::copy(other.spans_, other.spans_ + other.count_, spans_);
    return *this;
  }

  int size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const CsgSpan& operator[](int i) const { return spans_[i]; }
  const CsgSpan* begin() const { return spans_; }
  const CsgSpan* end() const { return spans_ + count_; }
  // True when a span was dropped for want of room (the farthest go first once sorted).
  bool truncated() const { return truncated_; }

  void clear() {
    count_ = 0;
    truncated_ = false;
  }
  // Appends a span of positive length (an empty or reversed one is no span at all).
  void add(const CsgSpan& s) {
    if (!(s.in.t < s.out.t)) return;
    if (count_ < kCapacity) spans_[count_++] = s;
    else add_to_full(s);
  }
  void sort_by_entry();
  void mark_truncated() { truncated_ = true; }

 private:
  void add_to_full(const CsgSpan& s);

  CsgSpan spans_[kCapacity];
  int count_ = 0;
  bool truncated_ = false;
};

// out = a (op) b. `out` must be neither input.
void csg_combine(CsgOp op, const CsgSpanList& a, const CsgSpanList& b, CsgSpanList& out);

// out = the boolean union of a's spans: sorted, disjoint, touching spans joined.
void csg_normalise(const CsgSpanList& a, CsgSpanList& out);

}  // namespace rt
