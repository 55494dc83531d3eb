// Proves the hot path allocates nothing: this test binary replaces the global operator new with
// a counting one, then traces rays through the BVH and shades pixels, and compares the counts.
#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include <catch2/catch.hpp>

#include "core/accel/bvh.h"
#include "core/color.h"
#include "core/render/pixel_sampler.h"
#include "core/rng.h"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
// The nothrow forms too: otherwise memory from the library's nothrow new (a sanitizer's
// allocator, say) would reach our free(), and the other way round.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept { return operator new(n, tag); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

using namespace rt;

namespace {

Scene small_scene() {
  Scene scene;
  scene.camera = Camera::look_at({0, 2, 6}, {0, 0, 0}, {0, 1, 0}, 50.0f);
  // Matte, mirror, glass with absorption, glossy: every integrator path is taken.
  Material mirror, glass, glossy;
  mirror.reflectivity = Vec3(0.8f);
  glass.kd = Vec3(0.0f);
  glass.transmission = Vec3(1.0f);
  glass.absorption = Vec3(0.5f, 0.1f, 0.2f);
  glossy.reflectivity = Vec3(0.7f);
  glossy.glossy = 0.2f;
  // Textures on them all: colour, specular (projected), bump and normal maps, trilinear.
  const auto ramp = [](int n) {
    std::vector<Vec3> texels;
    for (int i = 0; i < n * n; ++i) texels.push_back(Vec3(static_cast<float>(i % n) / static_cast<float>(n)));
    return Texture(n, n, texels);
  };
  auto assets = std::make_shared<SceneAssets>();
  assets->textures = {ramp(16), ramp(8), Texture(2, 2, std::vector<Vec3>(4, Vec3(0.6f, 0.4f, 0.9f)))};
  Material matte;
  matte.texture.texture = 0;
  matte.bump.height.texture = 1;
  mirror.normal_map.map.texture = 2;
  glossy.specular_texture.texture = 0;
  glossy.specular_texture.mapping.projection = Projection::kSpherical;
  glossy.specular_texture.mapping.scale = Vec2(3.0f, 2.0f);
  // A glTF-like material: metallic-roughness per point from a texture, emission, an alpha mask.
  Material leaf;
  leaf.pbr.enabled = true;
  leaf.pbr.metallic = 0.5f;
  leaf.pbr.roughness = 0.7f;
  leaf.pbr.texture.texture = 2;
  leaf.emission = Vec3(0.1f);
  leaf.cutout.enabled = true;
  leaf.cutout.texture.texture = 0;
  assets->materials = {matte, mirror, glass, glossy, leaf};
  scene.lights = {PointLight{{2, 5, 3}, Vec3(1.0f), {}},
                  RectLight{{-1, 4, -1}, {2, 0, 0}, {0, 0, 2}, Vec3(0.5f), {}, true}};
  PrimitiveSet prims;
  Rng rng(1);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 c(4 * rng.next_float() - 2, 4 * rng.next_float() - 2, 4 * rng.next_float() - 2);
    prims.triangles.push_back(PackedTriangle::from_vertices(c, c + Vec3(0.2f, 0, 0), c + Vec3(0, 0.2f, 0.1f)));
  }
  TriangleMesh mesh;
  for (const PackedTriangle& t : prims.triangles) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {t.v0, t.v0 + t.e1, t.v0 + t.e2});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
  }
  prims.triangles.clear();  // the mesh is placed as an instance of its own BVH
  MeshGeometry geometry{mesh, Bvh(make_triangle_set(mesh), {})};
  assets->meshes.push_back(std::move(geometry));
  // Glass (material 2): shadow rays pass through it with the any-hit visitor.
  prims.instances.push_back(place_mesh(assets->meshes[0].bvh, *make_transform(Mat4(1.0f)), 0, 2));
  // The same mesh again with the masked material: traversal tests its coverage at each crossing.
  assets->add_mask(0, 4, false);
  REQUIRE(assets->mask(0, 4));
  prims.instances.push_back(place_mesh(assets->meshes[0].bvh,
                                       *make_transform(compose_trs({1.5f, 1.5f, 0}, {0, 0, 0}, {0.25f, 0.25f, 0.25f})),
                                       0, 4, assets->mask(0, 4)));
  scene.assets = assets;
  for (ShapeKind k :
       {ShapeKind::kSphere, ShapeKind::kCylinder, ShapeKind::kCone, ShapeKind::kCube, ShapeKind::kPlane}) {
    AnalyticShape s;
    s.kind = k;
    s.material = static_cast<uint32_t>(k) % 4;
    s.transform = *make_transform(compose_trs({static_cast<float>(k) - 2.0f, -1, 0}, {10, 20, 30}, {0.5f, 0.7f, 0.4f}));
    prims.shapes.push_back(s);
  }
  // A glass CSG solid: a sphere minus a cube minus the glass mesh (a closed operand in parity terms
  // or not, its crossings go through the span lists all the same).
  CsgObject csg;
  const uint32_t root = csg.open(CsgOp::kDifference);
  for (const ShapeKind k : {ShapeKind::kSphere, ShapeKind::kCube}) {
    const uint32_t shape_leaf = csg.begin_leaf();
    CsgSurface s;
    s.shape = AnalyticShape{
        k, 2, *make_transform(compose_trs({0.5f, 0.5f, 1}, {0, 30, 0}, Vec3(k == ShapeKind::kSphere ? 1.0f : 0.5f)))};
    csg.add_surface(s);
    csg.close(shape_leaf);
  }
  const uint32_t mesh_leaf = csg.begin_leaf();
  CsgSurface m;
  m.is_mesh = true;
  m.mesh = place_mesh(assets->meshes[0].bvh, *make_transform(compose_trs({0.5f, 0.5f, 1}, {}, Vec3(0.3f))), 0, 2);
  m.triangles = &assets->meshes[0].mesh;
  csg.add_surface(m);
  csg.close(mesh_leaf);
  csg.close(root);
  csg.finish();
  prims.csgs.push_back(std::move(csg));
  scene.bvh = Bvh(prims, {});
  scene.emitters = Emitters(scene.bvh, *assets);  // the leaf material's mesh emits: light sampling draws it
  return scene;
}

// Everything a worker thread needs to render one 64 x 48 tile of small_scene() with `antialias`,
// built (and its allocations made) before a test starts counting.
struct OneTile {
  Scene scene = small_scene();
  RenderSettings settings;
  std::unique_ptr<Integrator> integrator;
  RayCounters counters;
  PixelContext ctx{scene, settings, *integrator, counters, 0};
  TileGrid grid{64, 48, 64};
  std::unique_ptr<PixelSampler> sampler;
  FilmTile film;

  explicit OneTile(const AntialiasSettings& antialias, const char* integrator_name = "whitted")
      : integrator(make_integrator(integrator_name)) {
    settings.integrator = integrator_name;
    settings.width = grid.window.width();
    settings.height = grid.window.height();
    settings.antialias = antialias;
    sampler = make_pixel_sampler(settings, grid);
    film.reset(grid.tile(0));
  }
  void render() { sampler->render_tile(grid.tile(0), ctx, film); }
};

}  // namespace

TEST_CASE(
    "tracing and shading (reflection, refraction, glossy, shadows through glass, textures, bumps, alpha masks, "
    "metallic-roughness, CSG) allocate nothing per ray",
    "[bvh][alloc]") {
  AntialiasSettings one_ray;  // one ray a pixel: the tracing alone
  one_ray.mode = "none";
  OneTile t{one_ray};
  const Scene& scene = t.scene;
  const RayCounters& counters = t.counters;

  const long before = g_allocations.load();
  Rng rng(3);
  int hits = 0, masked = 0, solid = 0;
  for (int i = 0; i < 20000; ++i) {
    Ray r;
    r.origin = Vec3(0, 0, 8);
    r.direction = glm::normalize(Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, -1.0f));
    Hit h;
    const bool hit = scene.intersect(r, h);
    hits += hit;
    masked += hit && scene.bvh.kind(h.prim) == PrimitiveKind::kInstance && scene.bvh.instance(h.prim).cutout != nullptr;
    solid += hit && scene.bvh.kind(h.prim) == PrimitiveKind::kCsg;
    hits += scene.occluded(r);
  }
  t.render();
  const long after = g_allocations.load();
  Vec3 sum(0.0f);
  for (int y = 0; y < t.grid.window.height(); ++y)
    for (int x = 0; x < t.grid.window.width(); ++x) sum += t.film.at(x, y).color;

  CHECK(hits > 1000);
  CHECK(masked > 0);  // the alpha-masked instance was traced
  CHECK(solid > 0);   // and the CSG solid
  CHECK(counters[RayKind::kShadow] > 0);
  CHECK(counters[RayKind::kReflection] > 0);
  CHECK(counters[RayKind::kRefraction] > 0);
  CHECK(counters[RayKind::kGlossy] > 0);
  CHECK(sum.x > 0.0f);
  CHECK(after - before == 0);
}

TEST_CASE("the adaptive sampler allocates a few buffers per tile, none per ray, and none with a worker's workspace",
          "[render][alloc][antialias]") {
  AntialiasSettings adaptive;
  adaptive.mode = "adaptive";
  adaptive.max_depth = 3;
  OneTile t{adaptive};
  const RayCounters& counters = t.counters;
  srgb8_table();  // made once, on its first use

  long before = g_allocations.load();
  t.render();
  long after = g_allocations.load();
  CHECK(counters[RayKind::kCamera] > 65u * 49u);  // some pixels were refined
  CHECK(after - before <= 6);                     // the tile's three borders and the row lattice's three buffers
  std::vector<Vec3> fresh;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) fresh.push_back(t.film.at(x, y).color);

  // A worker's buffers, first filled by a tile seen from elsewhere: what they keep from it (the
  // lattice's points, the borders) must not show in the next tile.
  const std::unique_ptr<SamplerWorkspace> workspace = t.sampler->make_workspace();
  REQUIRE(workspace);
  t.ctx.workspace = workspace.get();
  const Camera elsewhere = Camera::look_at({3, 1, 4}, {0, 0.5f, 0}, {0, 1, 0}, 35.0f);
  t.ctx.camera = &elsewhere;
  t.render();
  t.ctx.camera = nullptr;
  before = g_allocations.load();
  t.render();
  after = g_allocations.load();
  CHECK(after - before == 0);
  size_t differ = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) differ += t.film.at(x, y).color != fresh[static_cast<size_t>(y * 64 + x)];
  CHECK(differ == 0);
}

TEST_CASE("the path tracer allocates nothing per sample", "[render][alloc][path]") {
  OneTile t{AntialiasSettings{}, "path"};
  t.settings.path.samples_per_pixel = 4;
  t.settings.max_depth = 8;
  t.sampler = make_pixel_sampler(t.settings, t.grid);
  const RayCounters& counters = t.counters;
  REQUIRE_FALSE(t.scene.emitters.empty());

  const long before = g_allocations.load();
  t.render();
  const long after = g_allocations.load();
  CHECK(counters[RayKind::kCamera] == 64u * 48u * 4u);
  CHECK(counters[RayKind::kBounce] > 0);
  CHECK(counters[RayKind::kShadow] > 0);
  CHECK(after - before == 0);
}
