// The light sampling interface held to itself, per kind of light: each sample's own pdf against
// pdf_li at the point it drew, the density integrated over the sphere against the share of
// samples drawn, the directions' histogram against the density (chi-square: a rect light and the
// sky, whose densities are bounded), and what the estimator adds up to against a closed form (a
// furnace test: emissive shapes, meshes and CSG solids, whose densities per solid angle grow
// without bound at their silhouettes, where binned integrals are no good). The pdf of a direction
// is found as the path tracer finds it, from what a ray along it meets (a rect light's face, an
// emissive surface, the sky), summed over every surface the line crosses: sample_li may draw the
// far side of a shape, which the shadow ray then finds blocked.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/direction_sampling.h"
#include "core/render/scene_lights.h"
#include "core/shapes/shape_sampling.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

constexpr uint64_t kPath = 0;

// The densities per solid angle of light l's points along the half-line from `point` along
// `direction`, nearest first, as the path tracer finds them from what a ray meets: a rect light's
// face, each crossing of an emissive surface, or the sky when nothing is met. `distances` gets
// where each is.
std::vector<float> pdfs_along(const Scene& scene, size_t l, Vec3 point, Vec3 direction,
                              std::vector<float>* distances = nullptr) {
  std::vector<float> out;
  const auto add = [&](float pdf, float distance) {
    out.push_back(pdf);
    if (distances) distances->push_back(distance);
  };
  const size_t n = scene.lights.size();
  if (l < n) {
    const RectLight* rect = std::get_if<RectLight>(&scene.lights[l]);
    float t = 0.0f;
    if (rect && intersect_rect(*rect, Ray(point, direction), t)) add(pdf_li(*rect, direction, t), t);
    return out;
  }
  if (l == n + 1) {
    if (scene.background.is_image()) add(scene.background.pdf(direction), kInfinity);
    return out;
  }
  Ray ray(point, direction);
  for (int crossing = 0; crossing < 16; ++crossing) {
    Hit hit;
    Ray r = ray;
    if (!scene.intersect(r, hit)) break;
    const SurfaceInteraction si = scene.surface(r, hit);
    const float distance = glm::length(si.position - point);
    add(surface_pdf_li(scene, hit, si.geometric_normal, direction, distance), distance);
    ray.tmin = hit.t * (1.0f + 1e-5f) + 1e-5f;  // on past this crossing
  }
  return out;
}

float pdf_along(const Scene& scene, size_t l, Vec3 point, Vec3 direction) {
  float sum = 0.0f;
  for (float p : pdfs_along(scene, l, point, direction)) sum += p;
  return sum;
}

// pdf_li of the point a sample drew: the crossing along its direction at its distance.
float pdf_of_sample(const Scene& scene, size_t l, Vec3 point, const LightSample& ls) {
  std::vector<float> distances;
  const std::vector<float> pdfs = pdfs_along(scene, l, point, ls.direction, &distances);
  float pdf = -1.0f, nearest = 1e-3f * ls.distance;
  for (size_t i = 0; i < pdfs.size(); ++i)
    if (distances[i] == ls.distance || std::fabs(distances[i] - ls.distance) < nearest) {
      nearest = std::fabs(distances[i] - ls.distance);
      pdf = pdfs[i];
    }
  return pdf;
}

// Bins of the sphere equal in solid angle: kRows in cos(theta) (z), kColumns in phi.
constexpr int kRows = 16, kColumns = 32;
int bin_of(Vec3 d) {
  const int row = std::clamp(static_cast<int>((d.z + 1.0f) * 0.5f * kRows), 0, kRows - 1);
  float phi = std::atan2(d.y, d.x);
  if (phi < 0.0f) phi += 2.0f * kPi;
  const int column = std::clamp(static_cast<int>(phi / (2.0f * kPi) * kColumns), 0, kColumns - 1);
  return row * kColumns + column;
}

// Pearson's chi-square of the sampled directions' histogram against the expected counts, bins
// with fewer than 5 expected pooled; true when below the 0.1 % critical value (Wilson-Hilferty).
struct ChiSquare {
  double statistic = 0.0, critical = 0.0;
  int dof = 0;
  bool passes() const { return statistic < critical; }
};
ChiSquare chi_square(const std::vector<double>& observed, const std::vector<double>& expected) {
  ChiSquare c;
  double pooled_o = 0.0, pooled_e = 0.0;
  int bins = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5.0) {
      pooled_o += observed[i];
      pooled_e += expected[i];
      continue;
    }
    c.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++bins;
  }
  if (pooled_e >= 5.0) {
    c.statistic += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e;
    ++bins;
  } else if (pooled_o > 20.0) {
    c.statistic = 1e30;  // many samples where the density says there are almost none
  }
  c.dof = std::max(1, bins - 1);
  const double k = c.dof, z = 3.09;  // the 99.9th percentile of the normal
  c.critical = k * std::pow(1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k)), 3.0);
  return c;
}

struct LightCheck {
  ChiSquare chi;
  double mass = 0.0;             // the density integrated over the sphere
  double accepted = 0.0;         // the share of sample_li calls that drew a point
  double worst_pdf_error = 0.0;  // of a sample's own pdf against pdf_along its direction
};

// Draws `count` samples of light l from `point` and integrates pdf_along over the bins.
LightCheck check_light(const Scene& scene, size_t l, Vec3 point, int count = 100000) {
  LightCheck out;
  std::vector<double> observed(kRows * kColumns, 0.0), expected(kRows * kColumns, 0.0);
  int drawn = 0;
  for (int i = 0; i < count; ++i) {
    const SampleStream samples(7, 0, static_cast<uint64_t>(i), 0);
    const LightSample ls = sample_li(scene, l, point, samples, kPath, {});
    if (!(ls.pdf > 0.0f)) continue;
    ++drawn;
    observed[static_cast<size_t>(bin_of(ls.direction))] += 1.0;
    // A sample's own pdf is pdf_li of the point it drew (away from grazing angles, where a ray
    // along it may meet a neighbouring triangle or miss the edge it was aimed at).
    if (i % 97 == 0 && ls.cos_light > 0.2f) {
      const float at = pdf_of_sample(scene, l, point, ls);
      out.worst_pdf_error =
          std::max(out.worst_pdf_error, static_cast<double>(std::fabs(at - ls.pdf) / std::max(at, ls.pdf)));
    }
  }
  out.accepted = static_cast<double>(drawn) / count;
  // Each bin integrated on a 24 x 24 grid of its own.
  constexpr int kSub = 24;
  const double bin_solid_angle = 4.0 * kPi / (kRows * kColumns);
  for (int row = 0; row < kRows; ++row)
    for (int column = 0; column < kColumns; ++column) {
      double sum = 0.0;
      for (int a = 0; a < kSub; ++a)
        for (int b = 0; b < kSub; ++b) {
          const float z = -1.0f + 2.0f * (static_cast<float>(row) + (static_cast<float>(a) + 0.5f) / kSub) / kRows;
          const float phi =
              2.0f * kPi * (static_cast<float>(column) + (static_cast<float>(b) + 0.5f) / kSub) / kColumns;
          const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
          sum += pdf_along(scene, l, point, Vec3(r * std::cos(phi), r * std::sin(phi), z));
        }
      const double integral = sum / (kSub * kSub) * bin_solid_angle;
      out.mass += integral;
      expected[static_cast<size_t>(row * kColumns + column)] = integral * count;
    }
  out.chi = chi_square(observed, expected);
  return out;
}

Scene scene_of(const std::string& name, const std::string& nodes_and_lights) {
  return rt::test::load_scene_text(name, R"({ "camera": { "position": [0, 0, 9], "look_at": [0, 0, 0] },
    "materials": { "glow": { "kd": 0, "emission": [2, 1, 0.5] }, "grey": { "kd": 0.5 } },
    )" + nodes_and_lights + "}")
      .scene;
}

// `chi`: the histogram is tested too; `mass` < 0: the integral is not (an emissive surface's
// density per solid angle has no bound at its silhouette, and binned integrals miss by percents).
void require_consistent(const LightCheck& c, double mass, bool chi) {
  INFO("chi-square " << c.chi.statistic << " (critical " << c.chi.critical << ", " << c.chi.dof << " dof), mass "
                     << c.mass << ", accepted " << c.accepted << ", worst pdf error " << c.worst_pdf_error);
  if (chi) CHECK(c.chi.passes());
  if (mass >= 0.0) CHECK(c.mass == Approx(mass).epsilon(0.02));
  CHECK(c.worst_pdf_error < 2e-3);
}

// The irradiance at `point` (unit normal `normal`) from an emitter of radiance 1 filling the
// convex polygon `v` (all of it above the point's horizon): Lambert's formula, half the sum over
// its edges of the angle each subtends times the cosine of its plane with the normal.
double polygon_irradiance(Vec3 point, Vec3 normal, const std::vector<Vec3>& v) {
  double sum = 0.0;
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 a = glm::normalize(glm::dvec3(v[i] - point));
    const glm::dvec3 b = glm::normalize(glm::dvec3(v[(i + 1) % v.size()] - point));
    sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) *
           glm::dot(glm::dvec3(normal), glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * std::fabs(sum);
}

// The estimate of the irradiance at `point` (unit normal `normal`) from light l's red channel:
// its samples' radiance x cos / pdf where the shadow ray reaches them.
double estimated_irradiance(const Scene& scene, size_t l, Vec3 point, Vec3 normal, int count) {
  double sum = 0.0;
  for (int i = 0; i < count; ++i) {
    const LightSample ls = sample_li(scene, l, point, SampleStream(3, 0, 0, static_cast<uint32_t>(i)), kPath, {});
    if (!(ls.pdf > 0.0f)) continue;
    Ray shadow(point, ls.direction);
    shadow.tmax = ls.distance * (1.0f - 1e-4f);
    if (scene.occluded(shadow)) continue;
    sum += ls.radiance.x * std::max(0.0f, glm::dot(normal, ls.direction)) / ls.pdf;
  }
  return sum / count;
}

}  // namespace

TEST_CASE("light sampling: a rect light's directions follow pdf_li", "[lights][sampling]") {
  const Scene scene = scene_of("ls_rect.json", R"("lights": [ { "type": "rect", "corner": [-1, 1, -1.5],
    "edge1": [2, 0, 0.5], "edge2": [0, 0, 3], "color": 3 } ], "nodes": [])");
  const LightCheck c = check_light(scene, 0, Vec3(0.2f, 0.0f, 0.1f));
  CHECK(c.accepted == 1.0);
  require_consistent(c, 1.0, true);
}

TEST_CASE("light sampling: emissive triangles, shapes and CSG solids follow pdf_li", "[lights][sampling]") {
  const Vec3 from(0.3f, -0.2f, 3.5f);
  SECTION("a stretched, turned sphere, drawn uniformly by area (its far side too)") {
    const Scene scene = scene_of("ls_sphere.json", R"("nodes": [ { "shape": "sphere", "material": "glow",
      "transform": { "rotate": [20, 30, 0], "scale": [1.5, 0.7, 1] } } ])");
    REQUIRE(scene.emitters.size() == 1);
    const LightCheck c = check_light(scene, scene.lights.size(), from);
    CHECK(c.accepted == 1.0);
    require_consistent(c, -1.0, false);
  }
  SECTION("a cube, a cylinder, a cone and a plane together, weighed by area") {
    const Scene scene = scene_of("ls_shapes.json", R"("nodes": [
      { "shape": "cube", "material": "glow", "transform": { "translate": [-1.5, 0, 0], "rotate": [10, 40, 0], "scale": [0.5, 0.8, 0.6] } },
      { "shape": "cylinder", "material": "glow", "transform": { "translate": [1.2, -1, 0], "rotate": [-70, 0, 20], "scale": [0.5, 0.5, 1.2] } },
      { "shape": "cone", "material": "glow", "transform": { "translate": [0.5, 1, -1], "rotate": [30, 0, 0], "scale": [0.6, 0.9, 1] } },
      { "shape": "plane", "material": "glow", "transform": { "translate": [0, -2, 0], "rotate": [20, 0, 0], "scale": [2, 1, 1] } },
      { "shape": "sphere", "material": "grey", "transform": { "translate": [0, 0, 1.5], "scale": 0.3 } } ])");
    REQUIRE(scene.emitters.size() == 4);  // the grey sphere gives off nothing
    require_consistent(check_light(scene, scene.lights.size(), from), -1.0, false);
  }
  SECTION("a mesh's triangles") {
    const Scene scene = scene_of("ls_mesh.json", R"("nodes": [ { "mesh": { "file": ")" +
                                                     rt::test::source_path("scenes/models/knot.glb") +
                                                     R"(" }, "material": "glow", "transform": { "scale": 0.8 } } ])");
    REQUIRE(scene.emitters.size() > 100);
    require_consistent(check_light(scene, scene.lights.size(), from), -1.0, false);
  }
  SECTION("a CSG solid: points inside another operand are no sample; the rest keep the operand's density") {
    const Scene scene = scene_of("ls_csg.json", R"("nodes": [ { "csg": "difference", "material": "glow", "children": [
      { "shape": "cube", "transform": { "rotate": [0, 25, 0] } },
      { "shape": "sphere", "transform": { "translate": [0, 0.4, 0.3], "scale": 1.3 } } ] } ])");
    REQUIRE(scene.emitters.size() == 2);
    const LightCheck c = check_light(scene, scene.lights.size(), from);
    // The cube's faces outside the sphere and the sphere's surface inside the cube: neither all.
    CHECK(c.accepted > 0.2);
    CHECK(c.accepted < 0.9);
    require_consistent(c, -1.0, false);
  }
}

TEST_CASE("light sampling: an environment image's directions follow pdf_li", "[lights][sampling]") {
  const Scene scene =
      scene_of("ls_sky.json", R"("background": { "environment": ")" + rt::test::source_path("scenes/textures/sky.hdr") +
                                  R"(" }, "nodes": [])");
  REQUIRE(scene.background.is_image());
  require_consistent(check_light(scene, scene.lights.size() + 1, Vec3(0.0f)), 1.0, true);
}

TEST_CASE("light sampling: delta lights are one sample of their colour, attenuation and cone", "[lights][sampling]") {
  const Scene scene = scene_of("ls_delta.json", R"("lights": [
      { "type": "point", "position": [0, 4, 0], "color": 2, "attenuation": [0, 0, 1] },
      { "type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "color": 2, "inner_angle": 10, "outer_angle": 20 },
      { "type": "directional", "direction": [0, -1, 0], "color": 0.5 } ], "nodes": [])");
  for (size_t l = 0; l < 3; ++l) {
    CHECK(light_is_delta(scene, l));
    const LightSample ls = sample_li(scene, l, Vec3(0.0f), SampleStream(1, 0, 0, 0), kPath, {});
    CHECK(ls.delta);
    CHECK(ls.pdf == 1.0f);
    CHECK(ls.direction.y == Approx(1.0f));
  }
  CHECK(sample_li(scene, 0, Vec3(0.0f), SampleStream(1, 0, 0, 0), kPath, {}).radiance.x == Approx(2.0f / 16.0f));
  CHECK(sample_li(scene, 2, Vec3(5.0f, 0.0f, 0.0f), SampleStream(1, 0, 0, 0), kPath, {}).radiance.x == Approx(0.5f));
  // Outside the spot's outer cone: nothing.
  CHECK(sample_li(scene, 1, Vec3(4.0f, 0.0f, 0.0f), SampleStream(1, 0, 0, 0), kPath, {}).radiance.x == 0.0f);
  CHECK_FALSE(light_is_delta(scene, 3));  // the surfaces (none here) and the sky
}

TEST_CASE("light sampling furnace: what emissive shapes, meshes and CSG solids add up to", "[lights][sampling]") {
  const Vec3 point(0.0f), up(0.0f, 1.0f, 0.0f);
  constexpr int kCount = 200000;
  // A sphere of radius R at distance D lights a point facing its centre with pi L (R / D)^2
  // (L = 2, the red of "glow"). Light sampling draws the whole sphere; the near side blocks the
  // far side's shadow rays.
  const double sphere = kPi * 2.0 * (0.8 * 0.8) / 9.0;
  SECTION("a sphere") {
    const Scene scene = scene_of("lf_sphere.json", R"("nodes": [ { "shape": "sphere", "material": "glow",
      "transform": { "translate": [0, 3, 0], "scale": 0.8 } } ])");
    CHECK(estimated_irradiance(scene, scene.lights.size(), point, up, kCount) == Approx(sphere).epsilon(0.01));
  }
  SECTION("a CSG intersection of a big cube and that sphere: the sphere (the cube's faces are no sample)") {
    const Scene scene = scene_of("lf_csg.json", R"("nodes": [ { "csg": "intersection", "material": "glow",
      "transform": { "translate": [0, 3, 0] }, "children": [
        { "shape": "cube", "transform": { "rotate": [10, 20, 30], "scale": 1.5 } },
        { "shape": "sphere", "transform": { "scale": 0.8 } } ] } ])");
    CHECK(estimated_irradiance(scene, scene.lights.size(), point, up, kCount) == Approx(sphere).epsilon(0.015));
  }
  SECTION("a mesh: glTF's Box, a unit cube of 12 triangles, by Lambert's formula for its faces in view") {
    const Scene scene =
        scene_of("lf_box.json", R"("nodes": [ { "mesh": { "file": ")" +
                                    rt::test::source_path("../shared/gltf/Box/glTF/Box.gltf") +
                                    R"(" }, "material": "glow", "transform": { "translate": [0.4, 2, 0.3] } } ])");
    REQUIRE(scene.emitters.size() == 12);
    // From (1.5, 0, 1.6) the box [-0.1, 0.9] x [1.5, 2.5] x [-0.2, 0.8] shows three faces: its
    // bottom (y = 1.5) and its sides at x = 0.9 and z = 0.8.
    const Vec3 corner_view(1.5f, 0.0f, 1.6f);
    const auto face = [](int axis, float at, float lo0, float hi0, float lo1, float hi1) {
      const int a0 = (axis + 1) % 3, a1 = (axis + 2) % 3;
      std::vector<Vec3> v(4, Vec3(0.0f));
      const float c0[4] = {lo0, hi0, hi0, lo0}, c1[4] = {lo1, lo1, hi1, hi1};
      for (int k = 0; k < 4; ++k) {
        v[static_cast<size_t>(k)][axis] = at;
        v[static_cast<size_t>(k)][a0] = c0[k];
        v[static_cast<size_t>(k)][a1] = c1[k];
      }
      return v;
    };
    const double expected = 2.0 * (polygon_irradiance(corner_view, up, face(1, 1.5f, -0.2f, 0.8f, -0.1f, 0.9f)) +
                                   polygon_irradiance(corner_view, up, face(0, 0.9f, 1.5f, 2.5f, -0.2f, 0.8f)) +
                                   polygon_irradiance(corner_view, up, face(2, 0.8f, -0.1f, 0.9f, 1.5f, 2.5f)));
    CHECK(estimated_irradiance(scene, scene.lights.size(), corner_view, up, kCount) == Approx(expected).epsilon(0.01));
  }
}

TEST_CASE("light sampling: area_scale is how much a transform stretches a surface's area", "[lights][sampling]") {
  // A parallelogram of tangent vectors at a point of the sphere, through a rotating, shearing,
  // non-uniform transform: world area / object area against area_scale at the world normal.
  const auto t = make_transform(compose_trs(Vec3(1, 2, 3), Vec3(20, 35, -50), Vec3(1.5f, 0.4f, 2.2f)) *
                                Mat4(Vec4(1, 0, 0, 0), Vec4(0.3f, 1, 0, 0), Vec4(0, 0, 1, 0), Vec4(0, 0, 0, 1)));
  REQUIRE(t);
  for (const Vec3 n : {Vec3(0, 0, 1), glm::normalize(Vec3(1, -2, 0.5f)), glm::normalize(Vec3(-0.3f, 0.2f, -1))}) {
    Vec3 a, b;
    orthonormal_basis(n, a, b);
    const float object_area = glm::length(glm::cross(a, b));
    const float world_area = glm::length(glm::cross(t->vector_to_world(a), t->vector_to_world(b)));
    CHECK(area_scale(*t, t->normal_to_world_unit(n)) == Approx(world_area / object_area).epsilon(1e-4));
  }
  // Each shape's canonical area, and its points on its surface with their normals outward.
  for (const ShapeKind kind :
       {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kPlane, ShapeKind::kCylinder, ShapeKind::kCone}) {
    for (int i = 0; i < 64; ++i) {
      const ShapePoint p = sample_object_surface(
          kind, Vec2((static_cast<float>(i % 8) + 0.37f) / 8.0f, (static_cast<float>(i / 8) + 0.61f) / 8.0f));
      const SurfacePatch patch = object_space_patch(kind, p.position, p.part);
      INFO("kind " << static_cast<int>(kind) << " point " << p.position.x << ", " << p.position.y << ", "
                   << p.position.z);
      CHECK(glm::dot(patch.normal, p.normal) == Approx(1.0f).epsilon(1e-4));
      Ray towards(p.position + p.normal * 0.5f, -p.normal);  // from outside, straight at it
      Hit hit;
      REQUIRE(intersect_object_space(kind, towards, hit));
      CHECK(hit.t == Approx(0.5f).epsilon(1e-3));
      CHECK(hit.part == p.part);
    }
  }
  CHECK(object_area(ShapeKind::kCone) == Approx(kPi * (1.0 + std::sqrt(2.0))));
}
