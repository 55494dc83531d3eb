// The shading record of a hit: a uniform Phong material's, made inline (uniform_phong_surface), is
// field for field the one the full evaluation makes (evaluate_mapped_surface), and which materials
// count as uniform.
#include <catch2/catch.hpp>

#include "core/shapes/analytic_shape.h"
#include "materials/evaluated_surface.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

// A unit sphere hit by a ray along -z from (0.3, 0.2, 5), from outside or (at the far side) from inside.
SurfaceInteraction sphere_hit(bool from_inside) {
  AnalyticShape sphere;
  sphere.kind = ShapeKind::kSphere;
  sphere.material = 3;
  sphere.transform = *make_transform(compose_trs({1, 0, 0}, {0, 0, 0}, {2, 2, 2}));
  Ray r;
  r.origin = from_inside ? Vec3(1.3f, 0.2f, 0.0f) : Vec3(1.3f, 0.2f, 5.0f);
  r.direction = Vec3(0, 0, -1);
  Hit h;
  REQUIRE(intersect_shape(sphere, r, h));
  SurfaceInteraction si = shape_surface(sphere, r, h);
  REQUIRE(si.front_face == !from_inside);
  return si;
}

void check_same(const EvaluatedSurface& a, const EvaluatedSurface& b) {
  CHECK(a.position == b.position);
  CHECK(a.position_error == b.position_error);
  CHECK(a.shadow_lift == b.shadow_lift);
  CHECK(a.n == b.n);
  CHECK(a.ng == b.ng);
  CHECK(a.wo == b.wo);
  CHECK(a.entering == b.entering);
  CHECK(a.material == b.material);
  CHECK(a.medium == b.medium);
  CHECK(a.diffuse == b.diffuse);
  CHECK(a.specular == b.specular);
  CHECK(a.shininess == b.shininess);
  CHECK(a.reflectivity == b.reflectivity);
  CHECK(a.transmission == b.transmission);
  CHECK(a.transmission_factor == b.transmission_factor);
  CHECK(a.refraction_glossy == b.refraction_glossy);
  CHECK(a.ior == b.ior);
  CHECK(a.absorption == b.absorption);
  CHECK(a.glossy == b.glossy);
  CHECK(a.emission == b.emission);
  REQUIRE(a.pbr.has_value() == b.pbr.has_value());
  if (a.pbr) {
    CHECK(a.pbr->base_color == b.pbr->base_color);
    CHECK(a.pbr->metallic == b.pbr->metallic);
    CHECK(a.pbr->roughness == b.pbr->roughness);
    const EvaluatedLayers &la = a.pbr->layers, &lb = b.pbr->layers;
    CHECK(la.dielectric_f0 == lb.dielectric_f0);
    CHECK(la.dielectric_f90 == lb.dielectric_f90);
    CHECK(la.clearcoat == lb.clearcoat);
    CHECK(la.clearcoat_n == lb.clearcoat_n);
    CHECK(la.sheen_color == lb.sheen_color);
    CHECK(la.anisotropy_direction == lb.anisotropy_direction);
    CHECK(la.iridescence_thickness == lb.iridescence_thickness);
  }
  CHECK(a.prim == b.prim);
}

}  // namespace

TEST_CASE("evaluate_surface: a uniform Phong material's inline record is the full evaluation's",
          "[materials][evaluate]") {
  Material glass;
  glass.kd = Vec3(0.2f, 0.3f, 0.4f);
  glass.ks = Vec3(0.5f);
  glass.shininess = 300.0f;
  glass.reflectivity = Vec3(0.1f, 0.0f, 0.05f);
  glass.transmission = Vec3(1.0f, 0.85f, 0.55f);
  glass.ior = 1.33f;
  glass.absorption = Vec3(1.2f, 0.15f, 0.9f);
  glass.glossy = 0.05f;
  glass.emission = Vec3(0.0f, 0.25f, 0.5f);
  Material matte;
  matte.kd = Vec3(0.6f, 0.5f, 0.1f);
  const std::vector<Texture> textures;
  for (const Material& m : {glass, matte}) {
    REQUIRE(m.uniform_phong());
    for (bool inside : {false, true}) {
      SurfaceInteraction si = sphere_hit(inside);
      si.color = Vec4(0.5f, 0.25f, 1.0f, 1.0f);  // a mesh's COLOR_0 tints kd
      const Vec3 d = glm::normalize(Vec3(0.1f, -0.2f, -1.0f));
      const EvaluatedSurface fast = uniform_phong_surface(m, si, d);
      check_same(fast, evaluate_mapped_surface(m, si, d, textures, 0.01f, {}));
      check_same(fast, evaluate_surface_unit(m, si, d, textures, 0.01f));  // which takes it for these
      // Sanity on real numbers: the side the ray sees, kd less what passes through.
      CHECK(fast.n == (inside ? -si.shading_normal : si.shading_normal));
      CHECK(fast.diffuse == m.kd * Vec3(0.5f, 0.25f, 1.0f) * (Vec3(1.0f) - m.transmission));
      CHECK(fast.medium == 3);  // a shape's own material behind it
    }
  }
}

TEST_CASE("evaluate_surface: glTF's terms only on a glTF material's hit, an unlit one's neither",
          "[materials][evaluate]") {
  const std::vector<Texture> textures;
  const SurfaceInteraction si = sphere_hit(false);
  const Vec3 d = glm::normalize(Vec3(0.1f, -0.2f, -1.0f));
  Material phong;
  phong.kd = Vec3(0.6f, 0.5f, 0.1f);
  CHECK_FALSE(evaluate_mapped_surface(phong, si, d, textures, 0.0f, {}).pbr);
  CHECK_FALSE(uniform_phong_surface(phong, si, d).pbr);
  Material gltf;
  gltf.pbr.enabled = true;
  gltf.kd = Vec3(0.8f, 0.4f, 0.2f);  // the base colour
  gltf.pbr.metallic = 1.5f;          // clamped to 1
  gltf.pbr.roughness = 0.25f;
  const EvaluatedSurface s = evaluate_mapped_surface(gltf, si, d, textures, 0.0f, {});
  REQUIRE(s.pbr);
  CHECK(s.pbr->base_color == gltf.kd);
  CHECK(s.pbr->metallic == 1.0f);
  CHECK(s.pbr->roughness == 0.25f);
  CHECK(s.pbr->layers.dielectric_f90 == 1.0f);  // no extension: the core model's Fresnel
  Material unlit = gltf;
  unlit.unlit = true;  // shown as its colour: no model to sample
  const EvaluatedSurface shown = evaluate_mapped_surface(unlit, si, d, textures, 0.0f, {});
  CHECK_FALSE(shown.pbr);
  CHECK(shown.emission == gltf.kd);
}

TEST_CASE("evaluate_surface: what makes a material not uniform", "[materials][evaluate]") {
  CHECK(Material{}.uniform_phong());
  Material textured;
  textured.texture.texture = 0;
  CHECK_FALSE(textured.uniform_phong());
  Material bumpy;
  bumpy.bump.height.texture = 0;
  CHECK_FALSE(bumpy.uniform_phong());
  Material normal_mapped;
  normal_mapped.normal_map.map.texture = 1;
  CHECK_FALSE(normal_mapped.uniform_phong());
  Material glowing;
  glowing.emission_texture.texture = 0;
  CHECK_FALSE(glowing.uniform_phong());
  Material shiny;
  shiny.specular_texture.texture = 0;
  CHECK_FALSE(shiny.uniform_phong());
  Material clear;
  clear.transmission_texture.texture = 0;
  CHECK_FALSE(clear.uniform_phong());
  Material gltf;
  gltf.pbr.enabled = true;
  CHECK_FALSE(gltf.uniform_phong());
  Material unlit;
  unlit.unlit = true;
  CHECK_FALSE(unlit.uniform_phong());
}

TEST_CASE("evaluate_surface: the scene marks its uniform Phong materials", "[materials][evaluate]") {
  // textures.json: every material has a texture; refraction.json: glass and plain colours only.
  for (const auto& [file, uniform] : {std::pair{"scenes/textures.json", false}, {"scenes/refraction.json", true}}) {
    const LoadedScene s = rt::test::load_scene_file(rt::test::source_path(file));
    const std::vector<Material>& materials = s.scene.materials();
    REQUIRE(materials.size() >= 8);
    for (uint32_t i = 0; i < materials.size(); ++i) {
      CHECK(materials[i].uniform_phong() == uniform);
      CHECK(s.scene.is_uniform_phong(i) == uniform);
    }
    CHECK_FALSE(s.scene.is_uniform_phong(static_cast<uint32_t>(materials.size())));
  }
  // A scene built by hand, without the table, takes the general evaluation for every material.
  CHECK_FALSE(Scene{}.is_uniform_phong(0));
}
