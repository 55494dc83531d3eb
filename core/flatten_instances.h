// Which of a scene's mesh instances its top-level BVH holds as world-space triangles rather than
// as instances, as Cycles does with the objects it does not instance. A ray then walks one tree:
// not the top level and, at each instance box it enters, the ray moved into object space and
// handed to the mesh's own tree (each entry a transform and a walk's set-up). The Blender
// fixture's three meshes, path traced: 0.90-0.96x the time (docs/benchmark.md, "Round two, a
// twenty-third session"). The instances stay in the set, marked flattened: a hit is named as
// theirs (Bvh::relabel), and surfaces, materials and emitters read them as before.
//
// Only a mesh placed once is flattened: one placed many times is stored and walked once (400
// placements of a knot load in 0.01 s, against 1.36 s when every copy was made: docs/
// rendering.md). Left as instances too: an alpha-masked or single-sided placement (its test reads
// the mesh's own triangle ids, in object space), a mesh without a BVH (validate builds none and
// traces nothing), a placement whose world-space triangles are not all finite, and whatever would
// take the flattened triangles past kFlattenedTriangles: the top level is built again for each
// animation frame, and a large mesh's walk outweighs the step into it anyway.
#pragma once

#include <cstddef>
#include <vector>

#include "core/accel/primitives.h"
#include "core/scene_assets.h"

namespace rt {

inline constexpr size_t kFlattenedTriangles = size_t{1} << 16;

// Appends the world-space triangles of top's instances that qualify to top.triangles, with their
// owners, and marks those instances flattened; in placement order, while `budget` triangles last.
void flatten_instances(PrimitiveSet& top, const std::vector<MeshGeometry>& meshes, size_t budget = kFlattenedTriangles);

}  // namespace rt
