// cli/bench/ray_sets: the rays `rtcli bench` and tools/embree_compare trace, and their file.
#include <catch2/catch.hpp>

#include <filesystem>

#include "cli/bench/ray_sets.h"
#include "core/accel/bvh.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

PrimitiveSet one_box() {  // a unit cube's twelve triangles, 0..1 on each axis
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) mesh.positions.push_back(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  mesh.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return make_primitive_set({mesh}, {});
}

}  // namespace

TEST_CASE("ray sets: incoherent rays start outside the model's box and all enter it", "[bench]") {
  const PrimitiveSet prims = one_box();
  const std::vector<RaySet> sets = make_ray_sets(prims);
  REQUIRE(sets.size() == 3);
  CHECK(sets[0].name == "primary");
  CHECK(sets[0].rays.size() == 1920u * 1080u);
  const RaySet& incoherent = sets[1];
  REQUIRE(incoherent.rays.size() == kIncoherentRays);
  const Bvh bvh(prims, BvhBuildOptions{1});
  size_t hits = 0;
  for (size_t i = 0; i < incoherent.rays.size(); i += 997) {
    const Ray& r = incoherent.rays[i];
    const Vec3 o = r.origin;
    CHECK_FALSE((o.x >= 0 && o.x <= 1 && o.y >= 0 && o.y <= 1 && o.z >= 0 && o.z <= 1));
    CHECK(glm::length(r.direction) == Approx(1.0f).margin(1e-5));
    Ray copy = r;
    Hit hit;
    hits += bvh.intersect(copy, hit) ? 1 : 0;
  }
  CHECK(hits == (incoherent.rays.size() + 996) / 997);  // aimed into a convex box: every one hits
  // Occlusion rays: one from each primary hit, any-hit.
  CHECK(sets[2].occlusion);
  CHECK_FALSE(sets[2].rays.empty());
  // Deterministic: the same model gives the same rays.
  CHECK(make_ray_sets(prims)[1].rays[12345].direction == incoherent.rays[12345].direction);
}

TEST_CASE("ray sets: a file holds them exactly, and a damaged one is refused with a reason", "[bench]") {
  std::vector<RaySet> sets{{"a", false, {}}, {"shadow", true, {}}};
  Ray r;
  r.origin = Vec3(1.5f, -2.25f, 3.0f);
  r.direction = Vec3(0.0f, 0.6f, -0.8f);
  r.tmin = 0.001f;
  r.tmax = 42.0f;
  sets[0].rays = {r, Ray{}};
  sets[1].rays = {r};
  const std::string path = rt::test::output_path("sets.rays");
  std::string error;
  REQUIRE(write_ray_sets(path, sets, error));
  CHECK(std::filesystem::file_size(path) == 8 + 4 + (1 + 1 + 1 + 8 + 2 * 32) + (1 + 6 + 1 + 8 + 32));
  std::vector<RaySet> back;
  REQUIRE(read_ray_sets(path, back, error));
  REQUIRE(back.size() == 2);
  CHECK(back[0].name == "a");
  CHECK_FALSE(back[0].occlusion);
  CHECK(back[1].occlusion);
  CHECK(back[0].rays[0].origin == r.origin);
  CHECK(back[0].rays[0].direction == r.direction);
  CHECK(back[0].rays[0].tmin == r.tmin);
  CHECK(back[0].rays[0].tmax == r.tmax);
  CHECK(std::isinf(back[0].rays[1].tmax));

  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 5);
  CHECK_FALSE(read_ray_sets(path, back, error));
  CHECK_THAT(error, Catch::Contains("ray set 2 of 2 is cut short or malformed"));
  CHECK_FALSE(read_ray_sets(rt::test::source_path("README.md"), back, error));
  CHECK_THAT(error, Catch::Contains("is not a ray file"));
}
