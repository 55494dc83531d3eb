// The BVH queries that dominate a render, compiled once per instruction set: the closest hit, the
// closest hit under an alpha cutout, and occlusion. core/accel/bvh_kernels_impl.h is the one
// source; bvh_kernels_sse.cpp, _avx2.cpp and _avx512.cpp build it with their compiler flags, each
// into its own namespace (so that no inline function of one set can stand in for another's at
// link time). A Bvh keeps a pointer to the table of the set it was built for: one indirect call a
// query, none per node or primitive.
#pragma once

#include <cstdint>

#include "core/accel/isa.h"

namespace rt {

class Bvh;
struct AlphaCutout;
struct Ray;
struct Hit;

// A visitor of every crossing along a ray, called through a pointer: once per crossing found, which
// for a shadow ray is a handful, never per node or primitive. Returns true to stop.
using HitVisitorFn = bool (*)(void* visitor, const Hit& hit);

struct BvhKernels {
  Isa isa;
  bool (*intersect)(const Bvh& bvh, Ray& ray, Hit& hit);
  // intersect() without testing primitive `from` (Bvh::intersect_leaving).
  bool (*intersect_leaving)(const Bvh& bvh, Ray& ray, Hit& hit, uint32_t from);
  bool (*intersect_cutout)(const Bvh& bvh, Ray& ray, Hit& hit, const AlphaCutout& cutout);
  // Closest hits of count <= kPacketSize rays at once: bit i set when rays[i] hit hits[i].
  unsigned (*intersect_packet)(const Bvh& bvh, Ray* rays, Hit* hits, int count);
  bool (*occluded)(const Bvh& bvh, const Ray& ray);
  // Occlusion of count <= kPacketSize rays at once: bit i set when rays[i] is blocked.
  unsigned (*occluded_packet)(const Bvh& bvh, const Ray* rays, int count);
  // Bvh::for_each_hit's walk, the visitor called through `visit` (Bvh::visit_hits).
  bool (*visit_hits)(const Bvh& bvh, const Ray& ray, HitVisitorFn visit, void* visitor);
  // visit_hits for a ray that only leaf `leaf` can meet.
  bool (*visit_hits_in_leaf)(const Bvh& bvh, const Ray& ray, uint32_t leaf, HitVisitorFn visit, void* visitor);
};

// The table for `isa`. The caller checks isa_supported() first: a kernel of a set the CPU lacks
// stops the process with an illegal instruction.
const BvhKernels& bvh_kernels(Isa isa);

namespace isa_sse {
extern const BvhKernels kKernels;
}
namespace isa_avx2 {
extern const BvhKernels kKernels;
}
namespace isa_avx512 {
extern const BvhKernels kKernels;
}

}  // namespace rt
