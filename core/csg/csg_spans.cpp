#include "core/csg/csg_spans.h"

#include <algorithm>

namespace rt {

void CsgSpanList::add_to_full(const CsgSpan& s) {
  truncated_ = true;
  // Keep the nearer of the new span and the farthest held one.
  CsgSpan* farthest =
      std::max_element(spans_, spans_ + count_, [](const CsgSpan& x, const CsgSpan& y) { return x.in.t < y.in.t; });
  if (s.in.t < farthest->in.t) *farthest = s;
}

void CsgSpanList::sort_by_entry() {
  // Insertion sort: lists are short and usually sorted already.
  for (int i = 1; i < count_; ++i) {
    const CsgSpan s = spans_[i];
    int j = i;
    for (; j > 0 && spans_[j - 1].in.t > s.in.t; --j) spans_[j] = spans_[j - 1];
    spans_[j] = s;
  }
}

namespace {

// Both lists' spans in one, sorted by entry.
void concatenate(const CsgSpanList& a, const CsgSpanList& b, CsgSpanList& out) {
  out.clear();
  for (const CsgSpan& s : a) out.add(s);
  for (const CsgSpan& s : b) out.add(s);
  if (a.truncated() || b.truncated()) out.mark_truncated();
  out.sort_by_entry();
}

// Every overlap of a span of a with a span of b. The inside (medium) is a's.
void intersect(const CsgSpanList& a, const CsgSpanList& b, CsgSpanList& out) {
  out.clear();
  for (const CsgSpan& x : a) {
    for (const CsgSpan& y : b) {
      if (y.in.t >= x.out.t) break;  // b is sorted by entry
      CsgSpan s;
      s.in = x.in.t >= y.in.t ? x.in : y.in;
      s.out = x.out.t <= y.out.t ? x.out : y.out;
      s.medium = x.medium;
      out.add(s);  // no overlap: out before in, dropped
    }
  }
  if (a.truncated() || b.truncated()) out.mark_truncated();
  out.sort_by_entry();
}

// Each span of a with the (normal) spans of b cut out of it. Where a cut begins, the result
// leaves through b's entry surface, and where it ends enters through b's exit surface: the
// subtracted operand's surfaces bound the result there (turned to face out of it by the caller).
void subtract(const CsgSpanList& a, const CsgSpanList& b_normal, CsgSpanList& out) {
  out.clear();
  for (const CsgSpan& x : a) {
    CsgBoundary in = x.in;
    bool open = true;
    for (const CsgSpan& y : b_normal) {
      if (y.out.t <= in.t) continue;
      if (y.in.t >= x.out.t) break;
      if (y.in.t > in.t) out.add(CsgSpan{in, y.in, x.medium});
      if (y.out.t >= x.out.t) {
        open = false;
        break;
      }
      in = y.out;
    }
    if (open) out.add(CsgSpan{in, x.out, x.medium});
  }
  if (a.truncated() || b_normal.truncated()) out.mark_truncated();
  out.sort_by_entry();
}

}  // namespace

void csg_normalise(const CsgSpanList& a, CsgSpanList& out) {
  CsgSpanList sorted = a;
  sorted.sort_by_entry();
  out.clear();
  if (sorted.truncated()) out.mark_truncated();
  if (sorted.empty()) return;
  CsgSpan run = sorted[0];
  for (int i = 1; i < sorted.size(); ++i) {
    const CsgSpan& s = sorted[i];
    if (s.in.t <= run.out.t) {  // overlapping or touching: one solid, no wall between
      if (s.out.t > run.out.t) run.out = s.out;
    } else {
      out.add(run);
      run = s;
    }
  }
  out.add(run);
}

void csg_combine(CsgOp op, const CsgSpanList& a, const CsgSpanList& b, CsgSpanList& out) {
  switch (op) {
    case CsgOp::kUnion: concatenate(a, b, out); return;
    case CsgOp::kMerge: {
      CsgSpanList both;
      concatenate(a, b, both);
      csg_normalise(both, out);
      return;
    }
    case CsgOp::kIntersection: intersect(a, b, out); return;
    case CsgOp::kDifference: {
      if (b.size() <= 1) {  // normal already (a shape operand's one span): no copy to make
        subtract(a, b, out);
        return;
      }
      CsgSpanList cut;
      csg_normalise(b, cut);
      subtract(a, cut, out);
      return;
    }
  }
}

}  // namespace rt
