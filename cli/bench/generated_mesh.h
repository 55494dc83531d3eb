// A deterministic test mesh for benchmarks: a sphere with a rough, multi-frequency displaced
// surface (like a scanned stone), tessellated as a latitude-longitude grid. Dense, uneven and
// self-occluding, so BVH quality and ray throughput figures mean something.
#pragma once

#include "core/mesh.h"

namespace rt {

// At least `min_triangles` triangles.
TriangleMesh make_benchmark_mesh(size_t min_triangles);

}  // namespace rt
