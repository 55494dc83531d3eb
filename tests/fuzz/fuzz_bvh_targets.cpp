// The fuzz target of the BVH: its build from arbitrary triangles and every query on arbitrary
// rays, each held to brute force, to the baseline kernels or to another query's answer; and the
// packet walks on analytic shapes made from the same numbers, held to single rays.
#include <algorithm>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "core/accel/brute_force.h"
#include "core/accel/bvh.h"
#include "core/accel/bvh_traversal.h"
#include "core/flatten_instances.h"
#include "core/shapes/analytic_shape.h"
#include "core/transform.h"
#include "tests/fuzz/fuzz_targets.h"

namespace rt::fuzz {
namespace {

// Whether a hit found at distance t on a primitive whose own box is `box` is one the BVH must find
// too. Moller-Trumbore's rounding error (and a shape's) grows with the coordinates involved, so
// with huge or thin triangles it reports points outside the primitive's own box, which the BVH
// rightly culls. A hit counts when its point is inside the box by more than that error on every
// axis (so hits on primitives thinner than the error in some axis are not checked here;
// tests/core/test_bvh.cpp covers ordinary ones).
bool robust_in(const Aabb& box, const Ray& ray, float t) {
  const Vec3 p = ray.at(t);
  const float margin = 1e-5f * std::max({max_abs_component(box.lo), max_abs_component(box.hi),
                                         max_abs_component(ray.origin), max_abs_component(p), 1e-30f});
  for (int a = 0; a < 3; ++a)
    if (!(p[a] >= box.lo[a] + margin && p[a] <= box.hi[a] - margin)) return false;
  return true;
}
// robust_in for a triangle's own box.
bool robust_hit(const PackedTriangle& tri, const Ray& ray, float t) { return robust_in(tri.bounds(), ray, t); }

// A packet of the rays, repeated with shorter intervals: each gets its own occluded() answer,
// and its own closest hit, bit for bit, and its tmax narrowed alike. Except where rounding at
// extreme coordinates lets a primitive report a crossing outside its own box (not
// robust(prim, ray, t)): whether a walk meets that depends on which boxes it entered before
// narrowing tmax, and a packet enters them in another order. Such a hit may stand in for a
// farther one, but a robust hit is never missed or replaced by another.
template <class Robust>
std::string packets_agree(const Bvh& bvh, const std::vector<Ray>& valid, const Robust& robust,
                          const std::string& what) {
  if (valid.empty()) return "";
  Ray packet[kPacketSize];
  for (int i = 0; i < kPacketSize; ++i) {
    packet[i] = valid[static_cast<size_t>(i) % valid.size()];
    if (static_cast<size_t>(i) >= valid.size()) packet[i].tmax = static_cast<float>(i) * 0.5f;
  }
  for (int count = 1; count <= kPacketSize; ++count) {
    const unsigned mask = bvh.occluded_packet(packet, count);
    for (int i = 0; i < count; ++i)
      if (bool(mask >> i & 1u) != bvh.occluded(packet[i])) return what + "occluded_packet() and occluded() disagree";
    Ray walked[kPacketSize];
    Hit hits[kPacketSize];
    std::copy(packet, packet + count, walked);
    const unsigned found = bvh.intersect_packet(walked, hits, count);
    for (int i = 0; i < count; ++i) {
      Ray alone = packet[i];
      Hit h;
      const bool hit = bvh.intersect(alone, h), got = (found >> i & 1u) != 0;
      const bool same =
          hit == got && (!hit || (std::memcmp(&h.t, &hits[i].t, 4) == 0 && std::memcmp(&h.b1, &hits[i].b1, 4) == 0 &&
                                  std::memcmp(&h.b2, &hits[i].b2, 4) == 0 && h.prim == hits[i].prim &&
                                  h.part == hits[i].part && std::memcmp(&alone.tmax, &walked[i].tmax, 4) == 0));
      if (same) continue;
      const bool robust_alone = hit && robust(h.prim, packet[i], h.t);
      const bool robust_packet = got && robust(hits[i].prim, packet[i], hits[i].t);
      const bool packet_nearer_spurious = got && !robust_packet && hits[i].t <= h.t;
      const bool alone_nearer_spurious = hit && !robust_alone && h.t <= hits[i].t;
      if ((robust_alone && !packet_nearer_spurious) || (robust_packet && !alone_nearer_spurious))
        return what + "intersect_packet() and intersect() disagree";
    }
  }
  return "";
}

// The packet walks on analytic shapes made from the triangles' numbers (each nine a translation,
// rotation and scale, the kinds in turn), whose leaves test a packet's lanes at once
// (core/accel/shape_lanes.h), held to single rays as the triangles are (packets_agree).
std::string shape_packets(const float* v, size_t floats, unsigned threads, const std::vector<Ray>& valid) {
  if (valid.empty()) return "";
  const ShapeKind kinds[] = {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kPlane, ShapeKind::kCylinder,
                             ShapeKind::kCone};
  PrimitiveSet prims;
  for (size_t i = 0; i + 9 <= floats && prims.shapes.size() < 2000; i += 9) {
    const std::optional<Transform> t = make_transform(compose_trs(
        Vec3(v[i], v[i + 1], v[i + 2]), Vec3(v[i + 3], v[i + 4], v[i + 5]), Vec3(v[i + 6], v[i + 7], v[i + 8])));
    if (!t) continue;
    AnalyticShape shape;
    shape.kind = kinds[i / 9 % 5];
    shape.transform = *t;
    const Aabb box = world_bounds(shape);
    if (is_finite(box.lo) && is_finite(box.hi)) prims.shapes.push_back(shape);
  }
  if (prims.shapes.empty()) return "";
  const Bvh bvh(prims, BvhBuildOptions{threads});
  const auto robust = [&](uint32_t prim, const Ray& ray, float t) {
    return robust_in(world_bounds(bvh.shape(prim)), ray, t);
  };
  return packets_agree(bvh, valid, robust, "shapes: ");
}

// The triangles' corners as one mesh, placed once where it is and flattened into a top level
// (core/flatten_instances.h): the same triangles in the same order as the mesh's own BVH, so every
// query answers as that one does, under the instance's name (prim: the instance, part: the
// triangle). The identity placement may turn a vertex's -0 into +0: distances and barycentrics
// compare as floats.
std::string flattened_agree(const PrimitiveSet& prims, Isa isa, unsigned threads, const std::vector<Ray>& valid) {
  if (prims.triangles.empty() || valid.empty()) return "";
  std::vector<MeshGeometry> meshes(1);
  TriangleMesh& mesh = meshes[0].mesh;
  for (const PackedTriangle& t : prims.triangles) {
    for (const Vec3 p : {t.v0, t.v0 + t.e1, t.v0 + t.e2}) {
      mesh.indices.push_back(static_cast<uint32_t>(mesh.positions.size()));
      mesh.positions.push_back(p);
    }
  }
  const PrimitiveSet own = make_triangle_set(mesh);
  for (const PackedTriangle& t : own.triangles)
    if (!t.is_finite()) return "";  // a corner or edge that overflows once made from the edges
  meshes[0].bvh = Bvh(own, BvhBuildOptions{threads, isa});
  const Bvh& reference = meshes[0].bvh;
  PrimitiveSet top;
  top.instances.push_back(place_mesh(reference, Transform{}, 0, 0));
  flatten_instances(top, meshes);
  if (!top.instances[0].flattened) return "";  // past the budget, or not finite in the world
  const Bvh flat(top, BvhBuildOptions{threads, isa});
  if (std::string problem = flat.check_structure(); !problem.empty()) return "flattened BVH: " + problem;
  for (const Ray& original : valid) {
    Ray a = original, b = original;
    Hit ha, hb;
    const bool found_a = reference.intersect(a, ha), found_b = flat.intersect(b, hb);
    if (found_a != found_b) return "a flattened mesh and its own BVH disagree on a hit";
    if (found_a && (hb.prim != flat.primitive_count() - 1 || hb.part != ha.prim || ha.t != hb.t || ha.b1 != hb.b1 ||
                    ha.b2 != hb.b2))
      return "a flattened mesh's hit is not its own BVH's, under the instance's name";
    if (reference.occluded(original) != flat.occluded(original))
      return "a flattened mesh and its own BVH disagree on occlusion";
    std::vector<std::pair<uint32_t, float>> seen_reference, seen_flat;
    reference.for_each_hit(original, [&](const Hit& h) { return seen_reference.emplace_back(h.prim, h.t), false; });
    flat.for_each_hit(original, [&](const Hit& h) { return seen_flat.emplace_back(h.part, h.t), false; });
    std::sort(seen_reference.begin(), seen_reference.end());
    std::sort(seen_flat.begin(), seen_flat.end());
    if (seen_reference != seen_flat) return "a flattened mesh and its own BVH saw different crossings";
  }
  return "";
}

}  // namespace

std::string bvh_build(const uint8_t* data, size_t size) {
  if (size < 1) return "";
  const unsigned threads = 1 + data[0] % 2;
  std::vector<float> values((size - 1) / 4);
  if (!values.empty()) std::memcpy(values.data(), data + 1, values.size() * 4);
  // The last 48 bytes (12 floats) describe two rays; everything before them, triangles.
  const size_t ray_floats = std::min<size_t>(values.size(), 12);
  const size_t triangle_floats = values.size() - ray_floats;
  PrimitiveSet prims;
  for (size_t i = 0; i + 9 <= triangle_floats && prims.triangles.size() < 20000; i += 9) {
    const float* v = &values[i];
    const auto t =
        PackedTriangle::from_vertices(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]), Vec3(v[6], v[7], v[8]));
    if (t.is_finite()) prims.triangles.push_back(t);
  }
  const Bvh bvh(prims, BvhBuildOptions{threads});  // the best kernels this CPU runs
  if (std::string problem = bvh.check_structure(); !problem.empty()) return "BVH: " + problem;
  const Bvh baseline(prims, BvhBuildOptions{threads, Isa::kSse});
  const BruteForce brute(prims);
  std::vector<Ray> valid;
  for (size_t r = 0; r + 6 <= ray_floats; r += 6) {
    const float* v = &values[triangle_floats + r];
    Ray a;
    a.origin = Vec3(v[0], v[1], v[2]);
    const Vec3 d(v[3], v[4], v[5]);
    const float length = glm::length(d);
    if (!is_finite(a.origin) || !(length > 1e-6f) || !std::isfinite(length)) continue;
    a.direction = d / length;
    const Ray original = a;
    valid.push_back(original);
    Ray b = a;
    Hit ha, hb;
    const bool found_a = bvh.intersect(a, ha), found_b = brute.intersect(b, hb);
    const bool occluded = bvh.occluded(original);
    // Every instruction set finds the baseline's hit, bit for bit.
    Ray c = original;
    Hit hc;
    const bool found_c = baseline.intersect(c, hc);
    if (found_a != found_c || (found_a && (std::memcmp(&ha.t, &hc.t, 4) != 0 || std::memcmp(&ha.b1, &hc.b1, 4) != 0 ||
                                           std::memcmp(&ha.b2, &hc.b2, 4) != 0 || ha.prim != hc.prim)))
      return std::string("the ") + isa_name(bvh.isa()) + " kernels' closest hit differs from the baseline's";
    if (occluded != baseline.occluded(original))
      return std::string("the ") + isa_name(bvh.isa()) + " kernels' occlusion differs from the baseline's";
    // The BVH tests a subset of what brute force tests, with the same triangle test.
    if (found_a && (!found_b || ha.t < hb.t)) return "the BVH found a hit brute force did not";
    if (occluded && !found_b) return "occluded() found a hit brute force did not";
    if (found_b && robust_hit(prims.triangles[hb.prim], original, hb.t)) {
      if (!found_a || ha.t != hb.t) return "the BVH missed the closest hit brute force found";
      // Equal distances go to the lower id, as brute force's id order finds them.
      if (ha.prim != hb.prim) return "the BVH and brute force chose different primitives at the same distance";
      if (!occluded) return "occluded() missed a hit brute force found";
    }
    // The any-hit visitor: every crossing it reports is one brute force reports too, at the same
    // t, and each primitive at most once (triangles are crossed once).
    std::vector<std::pair<uint32_t, float>> seen_bvh, seen_brute;
    bvh.for_each_hit(original, [&](const Hit& h) { return seen_bvh.emplace_back(h.prim, h.t), false; });
    // The dispatched walk (visit_hits) sees the same crossings in the same order.
    std::vector<std::pair<uint32_t, float>> seen_kernel;
    auto record = [&](const Hit& h) { return seen_kernel.emplace_back(h.prim, h.t), false; };
    bvh.visit_hits(original, record);
    if (seen_kernel != seen_bvh) return "visit_hits and for_each_hit saw different crossings";
    brute.for_each_hit(original, [&](const Hit& h) { return seen_brute.emplace_back(h.prim, h.t), false; });
    std::sort(seen_bvh.begin(), seen_bvh.end());
    std::sort(seen_brute.begin(), seen_brute.end());
    for (size_t k = 0; k + 1 < seen_bvh.size(); ++k)
      if (seen_bvh[k].first == seen_bvh[k + 1].first) return "for_each_hit visited a triangle twice";
    if (!std::includes(seen_brute.begin(), seen_brute.end(), seen_bvh.begin(), seen_bvh.end()))
      return "for_each_hit reported a crossing brute force did not";
    if (seen_bvh.empty() != !occluded) return "for_each_hit and occluded() disagree";
    // A shadow volume along the ray (its origin, a small light 10 along it): the leaves it meets
    // (Bvh::leaves_meeting) hold every crossing of the walk there that lies inside its box.
    Vec3 side1, side2;
    orthonormal_basis(original.direction, side1, side2);
    const ShadowVolume volume(original.origin, original.at(10.0f) - 0.01f * (side1 + side2), 0.02f * side1,
                              0.02f * side2);
    if (BvhLeafSet leaves; bvh.leaves_meeting(volume, leaves)) {
      const Ray segment(original.origin, original.direction, 0.0f, 10.0f * (1.0f - 1e-4f));
      std::vector<std::pair<uint32_t, float>> walked, asked;
      bvh.for_each_hit(segment, [&](const Hit& h) { return walked.emplace_back(h.prim, h.t), false; });
      auto ask = [&](const Hit& h) { return asked.emplace_back(h.prim, h.t), false; };
      for (int k = 0; k < leaves.count; ++k) bvh.visit_hits_in_leaf(segment, leaves.leaf[k], ask);
      std::sort(asked.begin(), asked.end());
      for (const auto& w : walked)
        if (robust_hit(prims.triangles[w.first], segment, w.second) &&
            !std::binary_search(asked.begin(), asked.end(), w))
          return "a crossing inside a shadow volume lies in none of the leaves it meets";
    }
  }
  const auto robust = [&](uint32_t prim, const Ray& ray, float t) { return robust_hit(prims.triangles[prim], ray, t); };
  if (std::string problem = packets_agree(bvh, valid, robust, ""); !problem.empty()) return problem;
  if (std::string problem = flattened_agree(prims, bvh.isa(), threads, valid); !problem.empty()) return problem;
  return shape_packets(values.data(), triangle_floats, threads, valid);
}

}  // namespace rt::fuzz
