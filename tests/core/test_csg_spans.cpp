// Roth's span algebra on hand-made lists: every operation, touching spans, empty results and a
// nested tree, with the operand surface each result boundary comes from.
#include <catch2/catch.hpp>
#include <initializer_list>
#include <utility>

#include "core/csg/csg_spans.h"

using namespace rt;

namespace {

// Spans [in, out] of operand `surface` (its boundaries carry part 0 for entry, 1 for exit).
CsgSpanList spans(uint32_t surface, std::initializer_list<std::pair<float, float>> list) {
  CsgSpanList out;
  for (const auto& [in, out_t] : list)
    out.add(CsgSpan{CsgBoundary{in, surface, 0, 0, 0}, CsgBoundary{out_t, surface, 1, 0, 0}, surface});
  out.sort_by_entry();
  return out;
}

CsgSpanList combine(CsgOp op, const CsgSpanList& a, const CsgSpanList& b) {
  CsgSpanList out;
  csg_combine(op, a, b, out);
  return out;
}

struct Expected {
  float in, out;
  uint32_t in_surface, out_surface;
};

void check(const CsgSpanList& got, std::initializer_list<Expected> want) {
  REQUIRE(got.size() == static_cast<int>(want.size()));
  int i = 0;
  for (const Expected& e : want) {
    CHECK(got[i].in.t == e.in);
    CHECK(got[i].out.t == e.out);
    CHECK(got[i].in.surface == e.in_surface);
    CHECK(got[i].out.surface == e.out_surface);
    ++i;
  }
}

}  // namespace

TEST_CASE("CSG spans: merge joins overlapping and touching spans into one solid", "[csg]") {
  const CsgSpanList a = spans(0, {{1, 3}, {6, 7}}), b = spans(1, {{2, 4}, {7, 8}, {10, 11}});
  check(combine(CsgOp::kMerge, a, b), {{1, 4, 0, 1}, {6, 8, 0, 1}, {10, 11, 1, 1}});
}

TEST_CASE("CSG spans: union keeps each operand's spans, inner walls and all", "[csg]") {
  const CsgSpanList u = combine(CsgOp::kUnion, spans(0, {{1, 3}}), spans(1, {{2, 4}}));
  check(u, {{1, 3, 0, 0}, {2, 4, 1, 1}});
  // Four boundaries where merge has two.
  CHECK(combine(CsgOp::kMerge, spans(0, {{1, 3}}), spans(1, {{2, 4}})).size() == 1);
}

TEST_CASE("CSG spans: intersection keeps the overlaps, bounded by whichever surface is inside the other", "[csg]") {
  const CsgSpanList a = spans(0, {{1, 5}, {8, 9}}), b = spans(1, {{2, 3}, {4, 8.5f}});
  check(combine(CsgOp::kIntersection, a, b), {{2, 3, 1, 1}, {4, 5, 1, 0}, {8, 8.5f, 0, 1}});
  // Touching spans share no volume; disjoint ones none either.
  CHECK(combine(CsgOp::kIntersection, spans(0, {{0, 1}}), spans(1, {{1, 2}})).empty());
  CHECK(combine(CsgOp::kIntersection, spans(0, {{0, 1}}), spans(1, {{3, 4}})).empty());
  CHECK(combine(CsgOp::kIntersection, spans(0, {{0, 1}}), CsgSpanList{}).empty());
}

TEST_CASE("CSG spans: difference cuts the second operand's spans out of the first's", "[csg]") {
  // A pipe wall: [0, 10] minus the bore [2, 8] leaves two walls, the inner faces the bore's.
  check(combine(CsgOp::kDifference, spans(0, {{0, 10}}), spans(1, {{2, 8}})), {{0, 2, 0, 1}, {8, 10, 1, 0}});
  // A cut over the start, over the end, over all of it, and one that only touches.
  check(combine(CsgOp::kDifference, spans(0, {{0, 10}}), spans(1, {{-1, 3}})), {{3, 10, 1, 0}});
  check(combine(CsgOp::kDifference, spans(0, {{0, 10}}), spans(1, {{7, 12}})), {{0, 7, 0, 1}});
  CHECK(combine(CsgOp::kDifference, spans(0, {{0, 10}}), spans(1, {{-1, 11}})).empty());
  check(combine(CsgOp::kDifference, spans(0, {{0, 10}}), spans(1, {{10, 11}})), {{0, 10, 0, 0}});
  // Several cuts in one span, overlapping cuts taken as their union.
  check(combine(CsgOp::kDifference, spans(0, {{0, 10}}), spans(1, {{1, 2}, {4, 6}, {5, 7}})),
        {{0, 1, 0, 1}, {2, 4, 1, 1}, {7, 10, 1, 0}});
  // Nothing to cut from.
  CHECK(combine(CsgOp::kDifference, CsgSpanList{}, spans(1, {{1, 2}})).empty());
}

TEST_CASE("CSG spans: the medium of a result span is its first operand's", "[csg]") {
  const CsgSpanList d = combine(CsgOp::kDifference, spans(0, {{0, 10}}), spans(1, {{2, 8}}));
  for (const CsgSpan& s : d) CHECK(s.medium == 0u);
  const CsgSpanList i = combine(CsgOp::kIntersection, spans(2, {{0, 10}}), spans(1, {{2, 8}}));
  CHECK(i[0].medium == 2u);
}

TEST_CASE("CSG spans: a nested tree, (A merge B) minus (C intersect D)", "[csg]") {
  const CsgSpanList ab = combine(CsgOp::kMerge, spans(0, {{0, 4}}), spans(1, {{3, 9}}));
  const CsgSpanList cd = combine(CsgOp::kIntersection, spans(2, {{2, 6}}), spans(3, {{5, 8}}));
  check(cd, {{5, 6, 3, 2}});
  check(combine(CsgOp::kDifference, ab, cd), {{0, 5, 0, 3}, {6, 9, 2, 1}});
}

TEST_CASE("CSG spans: a union's overlapping spans are each cut on their own", "[csg]") {
  const CsgSpanList u = combine(CsgOp::kUnion, spans(0, {{0, 4}}), spans(1, {{2, 6}}));
  // Minus [3, 5]: both spans lose their part inside the cut; the inner walls at 2 and 4 stay.
  check(combine(CsgOp::kDifference, u, spans(2, {{3, 5}})), {{0, 3, 0, 2}, {2, 3, 1, 2}, {5, 6, 2, 1}});
}

TEST_CASE("CSG spans: a list past its capacity keeps its nearest spans and says so", "[csg]") {
  CsgSpanList many;
  for (int i = CsgSpanList::kCapacity + 4; i-- > 0;) {
    const float t = 2.0f * static_cast<float>(i);
    many.add(CsgSpan{CsgBoundary{t, 0, 0, 0, 0}, CsgBoundary{t + 1, 0, 0, 0, 0}, 0});
  }
  many.sort_by_entry();
  CHECK(many.size() == CsgSpanList::kCapacity);
  CHECK(many.truncated());
  CHECK(many[0].in.t == 0.0f);
  CHECK(many[CsgSpanList::kCapacity - 1].in.t == static_cast<float>(2 * (CsgSpanList::kCapacity - 1)));
  // Empty and reversed spans are no spans.
  CsgSpanList none;
  none.add(CsgSpan{CsgBoundary{1, 0, 0, 0, 0}, CsgBoundary{1, 0, 0, 0, 0}, 0});
  none.add(CsgSpan{CsgBoundary{2, 0, 0, 0, 0}, CsgBoundary{1, 0, 0, 0, 0}, 0});
  CHECK(none.empty());
}
