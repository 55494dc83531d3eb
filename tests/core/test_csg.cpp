// CSG solids against rays: the lens's boundaries against their analytic values, normals on
// subtracted surfaces, merge against union, closed mesh operands against the analytic shape,
// and the BVH against testing every primitive.
#include <catch2/catch.hpp>

#include "core/accel/brute_force.h"
#include "core/accel/bvh_traversal.h"
#include "core/csg_template.h"
#include "core/rng.h"
#include "core/scene.h"
#include "tests/support/geometry.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

namespace {

CsgSurface sphere(Vec3 centre, float radius, uint32_t material = 0) {
  CsgSurface s;
  s.shape = AnalyticShape{ShapeKind::kSphere, material, *make_transform(compose_trs(centre, Vec3(0), Vec3(radius)))};
  return s;
}

CsgSurface cube(Vec3 centre, float half, uint32_t material = 0) {
  CsgSurface s;
  s.shape = AnalyticShape{ShapeKind::kCube, material, *make_transform(compose_trs(centre, Vec3(0), Vec3(half)))};
  return s;
}

void leaf(CsgObject& c, const CsgSurface& s) {
  const uint32_t l = c.begin_leaf();
  c.add_surface(s);
  c.close(l);
}

CsgObject two(CsgOp op, const CsgSurface& a, const CsgSurface& b) {
  CsgObject c;
  const uint32_t root = c.open(op);
  leaf(c, a);
  leaf(c, b);
  c.close(root);
  c.finish();
  return c;
}

// A scene whose BVH holds just these solids.
Scene scene_of(std::vector<CsgObject> solids) {
  PrimitiveSet prims;
  prims.csgs = std::move(solids);
  Scene s;
  s.bvh = Bvh(prims, BvhBuildOptions{});
  return s;
}

int crossings(const Scene& s, const Ray& r) {
  int n = 0;
  s.bvh.for_each_hit(r, [&](const Hit&) {
    ++n;
    return false;
  });
  return n;
}

// The unit cube [-1, 1]^3 as 12 outward-wound triangles, 24 vertices (split per face, as exporters do).
TriangleMesh cube_mesh() {
  TriangleMesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      const uint32_t base = static_cast<uint32_t>(m.positions.size());
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (const Vec2 c : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
        Vec3 p(0.0f);
        p[axis] = sign;
        p[u] = c.x;
        p[v] = c.y * sign;  // mirrored on the negative side, so the winding stays outward
        m.positions.push_back(p);
      }
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
    }
  return m;
}

// 3 x 400 spheres under union, merge, difference (a slab minus them) and an intersection of 40
// overlapping ones, nested; `index`: whether operations of many children get their child index.
CsgObject many_operands(bool index) {
  Rng rng(5);
  const auto random_sphere = [&](float spread, float radius) {
    return sphere(Vec3(spread * (2 * rng.next_float() - 1), spread * (2 * rng.next_float() - 1),
                       0.5f * spread * (2 * rng.next_float() - 1)),
                  radius * (0.5f + rng.next_float()));
  };
  CsgObject c;
  const uint32_t root = c.open(CsgOp::kUnion);
  for (const CsgOp op : {CsgOp::kUnion, CsgOp::kMerge, CsgOp::kDifference}) {
    const uint32_t node = c.open(op);
    if (op == CsgOp::kDifference) leaf(c, cube(Vec3(0), 3.0f));
    for (int i = 0; i < 400; ++i) leaf(c, random_sphere(3.0f, 0.2f));
    c.close(node);
  }
  const uint32_t both = c.open(CsgOp::kIntersection);
  for (int i = 0; i < 40; ++i) leaf(c, sphere(Vec3(0.01f * static_cast<float>(i), 0, 0), 1.0f));
  c.close(both);
  c.close(root);
  c.finish(index);
  return c;
}

}  // namespace

TEST_CASE("CSG: a lens (two spheres intersected) is entered and left where the spheres say", "[csg]") {
  // Radius 2 at z = -1.5 and z = +1.5: the lens spans z in [-0.5, 0.5] on the axis.
  const Scene s = scene_of({two(CsgOp::kIntersection, sphere({0, 0, -1.5f}, 2), sphere({0, 0, 1.5f}, 2))});
  for (const float x : {0.0f, 0.3f, 1.0f}) {
    Ray r = make_ray({x, 0, 10}, {0, 0, -1});
    Hit h;
    REQUIRE(s.intersect(r, h));
    const float bulge = -1.5f + std::sqrt(4.0f - x * x);  // where the far sphere's front surface is
    CHECK(h.t == Approx(10.0f - bulge).epsilon(1e-5));
    CHECK(csg_surface_index(h) == 0u);  // the sphere at -1.5 bounds the front
    CHECK_FALSE(csg_leaving(h));
    // From just inside, the exit: on the other sphere, as far behind.
    Ray inside = make_ray({x, 0, 0}, {0, 0, -1});
    Hit out;
    REQUIRE(s.intersect(inside, out));
    CHECK(out.t == Approx(bulge).epsilon(1e-5));
    CHECK(csg_surface_index(out) == 1u);
    CHECK(csg_leaving(out));
  }
  // Beyond the rim (the spheres' circles meet at radius sqrt(4 - 1.5^2) = 1.3229): no lens.
  Ray wide = make_ray({1.33f, 0, 10}, {0, 0, -1});
  Hit h;
  CHECK_FALSE(s.intersect(wide, h));
}

TEST_CASE("CSG: normals on a subtracted surface point out of the result", "[csg]") {
  // A hollow ball: radius 1 minus radius 0.5. A ray down -z meets z = 1, 0.5, -0.5, -1.
  const Scene s = scene_of({two(CsgOp::kDifference, sphere({0, 0, 0}, 1), sphere({0, 0, 0}, 0.5f))});
  Ray r = make_ray({0, 0, 5}, {0, 0, -1});
  const float expected_z[] = {1.0f, 0.5f, -0.5f, -1.0f};
  const float expected_nz[] = {1.0f, -1.0f, 1.0f, -1.0f};  // outward: into the cavity at 0.5 and -0.5
  const bool expected_front[] = {true, false, true, false};
  for (int i = 0; i < 4; ++i) {
    Ray ray = r;
    Hit h;
    REQUIRE(s.intersect(ray, h));
    const SurfaceInteraction si = s.surface(ray, h);
    CHECK(si.position.z == Approx(expected_z[i]).margin(1e-5));
    CHECK(si.geometric_normal.z == Approx(expected_nz[i]).margin(1e-5));
    CHECK(si.shading_normal.z == Approx(expected_nz[i]).margin(1e-5));
    CHECK(si.front_face == expected_front[i]);
    r.tmin = h.t + 1e-4f;
  }
  Ray past = r;
  Hit none;
  CHECK_FALSE(s.intersect(past, none));
}

TEST_CASE("CSG: a merge of two spheres is crossed twice through the overlap, a union four times", "[csg]") {
  const CsgSurface a = sphere({-0.5f, 0, 0}, 1), b = sphere({0.5f, 0, 0}, 1);
  const Ray along_x = make_ray({-5, 0, 0}, {1, 0, 0});
  CHECK(crossings(scene_of({two(CsgOp::kMerge, a, b)}), along_x) == 2);
  CHECK(crossings(scene_of({two(CsgOp::kUnion, a, b)}), along_x) == 4);
  // Where only one sphere is, both give its two crossings.
  const Ray one = make_ray({-1.2f, -5, 0}, {0, 1, 0});
  CHECK(crossings(scene_of({two(CsgOp::kMerge, a, b)}), one) == 2);
  CHECK(crossings(scene_of({two(CsgOp::kUnion, a, b)}), one) == 2);
}

TEST_CASE("CSG: a die (cube intersect sphere, minus a pip) and its tight bound", "[csg]") {
  CsgObject die;
  const uint32_t root = die.open(CsgOp::kDifference);
  const uint32_t body = die.open(CsgOp::kIntersection);
  leaf(die, cube({0, 0, 0}, 1));
  leaf(die, sphere({0, 0, 0}, 1.4f));
  die.close(body);
  leaf(die, sphere({0, 0, 1.15f}, 0.3f));  // a pip sunk into the +z face
  die.close(root);
  die.finish();
  // The bound is the first operand's: the overlap of the cube's and the sphere's, a little padded.
  CHECK(die.bounds().hi.z == Approx(1.0f).epsilon(1e-3));
  CHECK(die.bounds().lo.x == Approx(-1.0f).epsilon(1e-3));
  const Scene s = scene_of({die});
  // Down the z axis: into the pip's hollow, whose floor is the pip sphere's bottom at z = 0.85.
  Ray r = make_ray({0, 0, 5}, {0, 0, -1});
  Hit h;
  REQUIRE(s.intersect(r, h));
  CHECK(h.t == Approx(5.0f - 0.85f).epsilon(1e-5));
  CHECK(csg_surface_index(h) == 2u);
  CHECK(s.surface(r, h).geometric_normal.z == Approx(1.0f).margin(1e-5));  // the hollow's floor faces up
  // Through a corner: the sphere rounds it off.
  Ray corner = make_ray({5, 5, 5}, glm::normalize(Vec3(-1)));
  REQUIRE(s.intersect(corner, h));
  CHECK(glm::length(corner.at(h.t)) == Approx(1.4f).epsilon(1e-5));
}

TEST_CASE("CSG: a closed mesh operand gives the spans of the analytic shape it matches", "[csg]") {
  MeshGeometry g;
  g.mesh = cube_mesh();
  CHECK(count_open_edges({&g.mesh}) == 0u);
  g.bvh = Bvh(make_triangle_set(g.mesh), BvhBuildOptions{});
  g.bounds = g.bvh.bounds();
  CsgSurface mesh_cube;
  mesh_cube.is_mesh = true;
  mesh_cube.mesh = place_mesh(g.bvh, *make_transform(Mat4(1.0f)), 0, 0);
  mesh_cube.triangles = &g.mesh;
  const Scene from_mesh = scene_of({two(CsgOp::kDifference, mesh_cube, sphere({0, 0, 0}, 1.2f))});
  const Scene from_shape = scene_of({two(CsgOp::kDifference, cube({0, 0, 0}, 1), sphere({0, 0, 0}, 1.2f))});
  Rng rng(7);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 o = Vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 6.0f - 3.0f;
    const Vec3 target = Vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 2.0f - 1.0f;
    Ray a = make_ray(o, target - o), b = a;
    Hit ha, hb;
    const bool ga = from_mesh.intersect(a, ha), gb = from_shape.intersect(b, hb);
    INFO("ray " << o.x << "," << o.y << "," << o.z << " -> " << target.x << "," << target.y << "," << target.z << " t "
                << ha.t << " " << hb.t);
    REQUIRE(ga == gb);
    if (!ga) continue;
    ++hits;
    CHECK(ha.t == Approx(hb.t).epsilon(1e-4));
    CHECK(csg_leaving(ha) == csg_leaving(hb));
  }
  CHECK(hits > 100);
  // Down the axes, through the edges where each face's two triangles meet: each face counts once.
  for (const Vec3 d : {Vec3(0, 0, -1), Vec3(0, -1, 0), Vec3(-1, 0, 0), glm::normalize(Vec3(-1, -1, 0))}) {
    Ray a = make_ray(-4.0f * d, d), b = a;
    Hit ha, hb;
    REQUIRE(from_mesh.intersect(a, ha) == from_shape.intersect(b, hb));
    CHECK(ha.t == Approx(hb.t).epsilon(1e-5));
  }
}

TEST_CASE("CSG: open edges are counted with vertices joined by position", "[csg]") {
  TriangleMesh m = cube_mesh();
  CHECK(count_open_edges({&m}) == 0u);
  m.indices.resize(m.indices.size() - 3);  // one triangle gone: its three edges are open
  CHECK(count_open_edges({&m}) == 3u);
}

TEST_CASE("CSG: the BVH's closest and any hits agree with testing every primitive", "[csg][bvh]") {
  PrimitiveSet prims;
  prims.shapes.push_back(AnalyticShape{ShapeKind::kSphere, 0, *make_transform(compose_trs({3, 0, 0}, {}, Vec3(1)))});
  prims.csgs.push_back(two(CsgOp::kDifference, cube({0, 0, 0}, 1), sphere({0.5f, 0.5f, 0.5f}, 0.9f)));
  prims.csgs.push_back(two(CsgOp::kMerge, sphere({-3, 0, 0}, 1), sphere({-3, 0.8f, 0}, 0.7f)));
  const Bvh bvh(prims, BvhBuildOptions{});
  REQUIRE(bvh.check_structure().empty());
  const BruteForce brute(prims);
  Rng rng(11);
  for (int i = 0; i < 500; ++i) {
    const Vec3 o = Vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 12.0f - 6.0f;
    const Vec3 d = glm::normalize(Vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f);
    Ray a = make_ray(o, d), b = a;
    Hit ha, hb;
    REQUIRE(bvh.intersect(a, ha) == brute.intersect(b, hb));
    if (ha.prim != kNoPrimitive) {
      CHECK(ha.prim == hb.prim);
      CHECK(ha.t == hb.t);
    }
    int n_bvh = 0, n_brute = 0;
    bvh.for_each_hit(make_ray(o, d), [&](const Hit&) { return ++n_bvh, false; });
    brute.for_each_hit(make_ray(o, d), [&](const Hit&) { return ++n_brute, false; });
    CHECK(n_bvh == n_brute);
  }
}

TEST_CASE("CSG: an operation of many operands finds through its child index exactly the spans of the plain walk",
          "[csg]") {
  // Each line's spans, with and without the child indices, bit for bit.
  const CsgObject indexed = many_operands(true), plain = many_operands(false);
  Rng rng(6);
  int spans = 0, differences = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 o(8 * (2 * rng.next_float() - 1), 8 * (2 * rng.next_float() - 1), 8 * (2 * rng.next_float() - 1));
    const Vec3 target(3 * (2 * rng.next_float() - 1), 3 * (2 * rng.next_float() - 1), 3 * (2 * rng.next_float() - 1));
    const Ray line = make_ray(o, target - o);
    CsgSpanList a, b;
    indexed.spans(line, a);
    plain.spans(line, b);
    spans += a.size();
    if (a.size() != b.size()) {
      ++differences;
      continue;
    }
    for (int k = 0; k < a.size(); ++k) {
      const CsgSpan &x = a[k], &y = b[k];
      if (x.in.t != y.in.t || x.out.t != y.out.t || x.in.surface != y.in.surface || x.out.surface != y.out.surface ||
          x.medium != y.medium)
        ++differences;
    }
  }
  CHECK(differences == 0);
  CHECK(spans > 20000);  // the lines do cross the solid, many times
}

TEST_CASE("CSG: spans found within a ray's reach give exactly the whole line's hits and crossings", "[csg]") {
  // Rays that start on the solid, inside it and outside, their intervals ending inside it, beyond
  // it and never: the closest hit and every crossing from the spans in reach (what the BVH asks)
  // against those the whole line's spans give, bit for bit.
  const CsgObject solid = many_operands(true);
  Rng rng(8);
  int crossings_seen = 0, differences = 0, shorter_lists = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 o(8 * (2 * rng.next_float() - 1), 8 * (2 * rng.next_float() - 1), 8 * (2 * rng.next_float() - 1));
    const Vec3 target(3 * (2 * rng.next_float() - 1), 3 * (2 * rng.next_float() - 1), 3 * (2 * rng.next_float() - 1));
    Ray ray = make_ray(o, target - o);  // target at t = 1
    ray.tmin = i % 3 == 0 ? 0.0f : 1.2f * rng.next_float();
    ray.tmax = i % 4 == 0 ? kInfinity : ray.tmin + 1.5f * rng.next_float();
    if (i % 5 == 0) {  // from a boundary of the solid, as a secondary ray leaves it
      CsgSpanList line;
      solid.spans(ray, line);
      if (!line.empty()) {
        ray.origin = ray.at(line[0].out.t);
        ray.tmin = 0.0f;
      }
    }
    // The whole line's boundaries in the interval, as visit_csg_crossings takes them.
    CsgSpanList whole, in_reach;
    solid.spans(ray, whole);
    solid.spans_in_reach(ray, in_reach);
    if (in_reach.size() < whole.size()) ++shorter_lists;
    std::vector<Hit> expected, found;
    for (const CsgSpan& s : whole)
      for (int leaving = 0; leaving < 2; ++leaving) {
        const CsgBoundary& b = leaving ? s.out : s.in;
        if (b.t < ray.tmax && csg_boundary_in_reach(solid, b, ray))
          expected.push_back(csg_hit(b, leaving != 0, s.medium, 7));
      }
    std::stable_sort(expected.begin(), expected.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
    auto collect = [&](const Hit& h) {
      found.push_back(h);
      return false;
    };
    visit_csg_crossings(solid, 7, ray, collect);
    crossings_seen += static_cast<int>(found.size());
    bool same = found.size() == expected.size();
    for (size_t k = 0; same && k < found.size(); ++k)
      same = found[k].t == expected[k].t && found[k].operand == expected[k].operand &&
             found[k].medium == expected[k].medium;
    // The closest: the nearest of the expected crossings.
    Hit closest;
    const bool hit = intersect_csg(solid, ray, closest);
    const Hit* nearest = nullptr;
    for (const Hit& h : expected)
      if (!nearest || h.t < nearest->t) nearest = &h;
    same = same && hit == (nearest != nullptr) &&
           (!hit || (closest.t == nearest->t && closest.operand == nearest->operand));
    if (!same) ++differences;
  }
  CHECK(differences == 0);
  CHECK(crossings_seen > 20000);
  CHECK(shorter_lists > 2000);  // the reach does leave operands out
}

TEST_CASE("CSG: the origin's rounding bound holds every operand surface's rounding", "[csg]") {
  // Operands stretched, sheared, turned and far from the world's origin; rays from near and far:
  // the solid's one bound per ray is never below a surface's own rounding, and a boundary just
  // past it is in reach by either rule.
  Rng rng(9);
  int checked = 0, near_tmin = 0;
  for (int solid = 0; solid < 50; ++solid) {
    CsgObject c;
    const uint32_t root = c.open(CsgOp::kMerge);
    for (int k = 0; k < 4; ++k) {
      const Vec3 at = (Vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f) * 200.0f;
      const Vec3 turn = Vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 360.0f;
      const Vec3 scale = Vec3(0.01f) + Vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 20.0f;
      Mat4 m = compose_trs(at, turn, scale);
      m[1][0] += 3.0f * rng.next_float();  // a shear
      CsgSurface s;
      s.shape = AnalyticShape{k % 2 ? ShapeKind::kCube : ShapeKind::kSphere, 0, *make_transform(m)};
      leaf(c, s);
    }
    c.close(root);
    c.finish();
    for (int i = 0; i < 200; ++i) {
      const float reach = i % 2 ? 1.0f : 1000.0f;
      const Vec3 o = (Vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f) * reach;
      const Vec3 d = (Vec3(rng.next_float(), rng.next_float(), rng.next_float()) - 0.5f) * (i % 3 ? 1.0f : 0.001f);
      const Ray ray = make_ray(o, d);
      const float bound = c.rounding_bound(ray);
      for (const CsgSurface& s : c.surfaces()) {
        const Transform& t = s.transform();
        const float own = origin_rounding(t, o, t.vector_to_object(d));
        CHECK(own <= bound);
        ++checked;
        if (own > 0.01f * bound) ++near_tmin;  // the bound is not loose by orders of magnitude
      }
      for (const float past : {0.5f, 1.0f, 1.5f, 3.0f}) {
        const CsgBoundary b{ray.tmin + past * bound, 0, 0, 0.0f, 0.0f};
        CHECK(csg_boundary_in_reach(c, b, ray, bound) == csg_boundary_in_reach(c, b, ray));
      }
    }
  }
  CHECK(checked == 50 * 200 * 4);
  CHECK(near_tmin > checked / 2);
}
