// The path tracer's BSDFs (materials/bsdf.h), each lobe on its own and mixed: sampling matches the
// density (a chi-square test over the sphere of directions, as pbrt and Mitsuba test theirs), the
// density is > 0 wherever sampling goes, f is reciprocal, and no white surface reflects more than
// it receives (numeric integration over the sphere).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <iterator>
#include <vector>

#include "core/rng.h"
#include "materials/bsdf.h"

using namespace rt;

namespace {

Vec3 direction(float theta_degrees, float phi_degrees) {
  const float t = radians(theta_degrees), p = radians(phi_degrees);
  return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

// A surface facing +z seen from wo.
EvaluatedSurface surface(Vec3 wo) {
  EvaluatedSurface s;
  s.wo = glm::normalize(wo);
  s.n = s.ng = Vec3(0.0f, 0.0f, 1.0f);
  return s;
}

EvaluatedSurface lambert(Vec3 wo, float albedo) {
  EvaluatedSurface s = surface(wo);
  s.diffuse = Vec3(albedo);
  return s;
}
EvaluatedSurface phong(Vec3 wo, float kd, float ks, float shininess) {
  EvaluatedSurface s = surface(wo);
  s.diffuse = Vec3(kd);
  s.specular = Vec3(ks);
  s.shininess = shininess;
  return s;
}
EvaluatedSurface glossy(Vec3 wo, float reflectivity, float width) {
  EvaluatedSurface s = surface(wo);
  s.reflectivity = Vec3(reflectivity);
  s.glossy = width;
  return s;
}
EvaluatedSurface metal_rough(Vec3 wo, Vec3 base, float metallic, float roughness) {
  EvaluatedSurface s = surface(wo);
  s.pbr = PbrSurfaceTerms{.base_color = base, .metallic = metallic, .roughness = roughness};
  return s;
}

// Cells of the sphere: theta and phi split evenly (even in theta, not cos theta, so that a sharp
// lobe near the pole still spans many integration points).
constexpr int kThetaCells = 36, kPhiCells = 40;

int cell_of(Vec3 w) {
  const float theta = std::acos(std::clamp(w.z, -1.0f, 1.0f));
  const int i = std::clamp(static_cast<int>(theta / kPi * kThetaCells), 0, kThetaCells - 1);
  float phi = std::atan2(w.y, w.x);
  if (phi < 0.0f) phi += 2.0f * kPi;
  const int j = std::clamp(static_cast<int>(phi / (2.0f * kPi) * kPhiCells), 0, kPhiCells - 1);
  return i * kPhiCells + j;
}

// Integrates fn(direction) dw over each cell with an n x n midpoint grid in (theta, phi).
template <class Fn>
std::vector<double> integrate_cells(Fn&& fn, int n = 12) {
  std::vector<double> out(kThetaCells * kPhiCells, 0.0);
  const double d_theta = kPi / kThetaCells / double(n), d_phi = 2.0 * kPi / kPhiCells / double(n);
  for (int i = 0; i < kThetaCells; ++i)
    for (int j = 0; j < kPhiCells; ++j) {
      double sum = 0.0;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const double theta = (i * n + a + 0.5) * d_theta, phi = (j * n + b + 0.5) * d_phi;
          const Vec3 w(static_cast<float>(std::sin(theta) * std::cos(phi)),
                       static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
          sum += fn(w) * std::sin(theta) * d_theta * d_phi;
        }
      out[static_cast<size_t>(i * kPhiCells + j)] = sum;
    }
  return out;
}

struct ChiSquare {
  double statistic = 0.0;
  int dof = 0;
  double z = 0.0;  // Wilson-Hilferty: standard normal under the hypothesis
  int lost = 0;
  double expected_lost = 0.0;
};

// Pearson's test of `count` samples of the BSDF's smooth lobes against its pdf; cells expecting
// fewer than 5 samples are pooled.
ChiSquare chi_square(const Bsdf& bsdf, int count, uint64_t seed) {
  std::vector<double> observed(kThetaCells * kPhiCells, 0.0);
  Rng rng(seed);
  ChiSquare c;
  for (int k = 0; k < count; ++k) {
    BsdfSample s;
    const float lobe = rng.next_float();
    const Vec2 u(rng.next_float(), rng.next_float());
    if (!bsdf.sample(lobe, u, s) || s.delta) {
      ++c.lost;
      continue;
    }
    observed[static_cast<size_t>(cell_of(s.wi))] += 1.0;
  }
  // Fine enough for the sharpest lobe tested (Phong n = 200: about 4 degrees wide).
  const std::vector<double> mass = integrate_cells([&](Vec3 w) { return bsdf.pdf(w); }, 32);
  double pooled_o = 0.0, pooled_e = 0.0, total_mass = 0.0;
  for (size_t i = 0; i < mass.size(); ++i) {
    total_mass += mass[i];
    const double e = mass[i] * count;
    if (e < 5.0) {
      pooled_o += observed[i];
      pooled_e += e;
      continue;
    }
    c.statistic += (observed[i] - e) * (observed[i] - e) / e;
    ++c.dof;
  }
  if (pooled_e > 0.0) {
    c.statistic += (pooled_o - pooled_e) * (pooled_o - pooled_e) / std::max(pooled_e, 1.0);
    ++c.dof;
  }
  c.expected_lost = (1.0 - total_mass) * count;
  const double k = c.dof - 1;
  c.z = (std::cbrt(c.statistic / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
  return c;
}

// The directional albedo: the integral of f |cos| over the sphere, numerically.
double albedo(const Bsdf& bsdf) {
  double sum = 0.0;
  for (const double v :
       integrate_cells([&](Vec3 w) { return (bsdf.eval(w).x + bsdf.eval(w).y + bsdf.eval(w).z) / 3.0f; }, 24))
    sum += v;
  return sum;
}

// glTF's layered extensions over a metallic-roughness base.
EvaluatedSurface clearcoat(Vec3 wo, float coat_roughness) {
  EvaluatedSurface s = metal_rough(wo, Vec3(0.8f, 0.3f, 0.2f), 0.0f, 0.6f);
  s.pbr->layers.clearcoat = 1.0f;
  s.pbr->layers.clearcoat_roughness = coat_roughness;
  s.pbr->layers.clearcoat_n = Vec3(0.0f, 0.0f, 1.0f);
  return s;
}
EvaluatedSurface sheen(Vec3 wo, Vec3 base, float metallic, float sheen_roughness) {
  EvaluatedSurface s = metal_rough(wo, base, metallic, 0.5f);
  s.pbr->layers.sheen_color = Vec3(1.0f, 0.9f, 0.8f);
  s.pbr->layers.sheen_roughness = sheen_roughness;
  return s;
}
EvaluatedSurface anisotropic(Vec3 wo, float strength) {
  EvaluatedSurface s = metal_rough(wo, Vec3(0.95f), 1.0f, 0.3f);
  s.pbr->layers.anisotropy = strength;
  s.pbr->layers.anisotropy_direction = glm::normalize(Vec3(1.0f, 1.0f, 0.0f));
  return s;
}
EvaluatedSurface iridescent(Vec3 wo, float metallic) {
  EvaluatedSurface s = metal_rough(wo, Vec3(0.9f, 0.6f, 0.3f), metallic, 0.4f);
  s.pbr->layers.iridescence = 1.0f;
  s.pbr->layers.iridescence_thickness = 350.0f;
  return s;
}
EvaluatedSurface specular_colour(Vec3 wo) {
  EvaluatedSurface s = metal_rough(wo, Vec3(0.5f), 0.0f, 0.5f);
  s.pbr->layers.dielectric_f0 = Vec3(0.02f, 0.04f, 0.08f) * 0.7f;
  s.pbr->layers.dielectric_f90 = 0.7f;
  return s;
}

struct Case {
  const char* name;
  EvaluatedSurface (*make)(Vec3 wo);
  float eta = 1.0f;  // past the surface over before it (the rough dielectric's)
};

EvaluatedSurface rough_glass(Vec3 wo, float roughness) {
  EvaluatedSurface s = metal_rough(wo, Vec3(1.0f), 0.0f, roughness);
  s.transmission = Vec3(1.0f);
  s.transmission_factor = 1.0f;
  return s;
}

const Case kSmoothCases[] = {
    {"Lambert", [](Vec3 wo) { return lambert(wo, 1.0f); }},
    {"Phong kd 0.5 ks 0.5 n 20", [](Vec3 wo) { return phong(wo, 0.5f, 0.5f, 20.0f); }},
    {"Phong ks 1 n 200", [](Vec3 wo) { return phong(wo, 0.0f, 1.0f, 200.0f); }},
    {"glossy width 0.3", [](Vec3 wo) { return glossy(wo, 1.0f, 0.3f); }},
    {"GGX metal roughness 0.5", [](Vec3 wo) { return metal_rough(wo, Vec3(1.0f), 1.0f, 0.5f); }},
    {"GGX metal roughness 0.2", [](Vec3 wo) { return metal_rough(wo, Vec3(1.0f), 1.0f, 0.2f); }},
    {"GGX dielectric roughness 0.6", [](Vec3 wo) { return metal_rough(wo, Vec3(1.0f), 0.0f, 0.6f); }},
    {"GGX half metal roughness 0.35", [](Vec3 wo) { return metal_rough(wo, Vec3(0.9f, 0.5f, 0.2f), 0.5f, 0.35f); }},
    {"rough glass ior 1.5 roughness 0.3", [](Vec3 wo) { return rough_glass(wo, 0.3f); }, 1.5f},
    {"rough glass leaving, ior 1/1.5 roughness 0.5", [](Vec3 wo) { return rough_glass(wo, 0.5f); }, 1.0f / 1.5f},
    {"clearcoat roughness 0.3 over a rough dielectric", [](Vec3 wo) { return clearcoat(wo, 0.3f); }},
    {"smooth clearcoat (a mirror) over a rough dielectric", [](Vec3 wo) { return clearcoat(wo, 0.0f); }},
    {"sheen roughness 0.5 over a dielectric", [](Vec3 wo) { return sheen(wo, Vec3(0.8f), 0.0f, 0.5f); }},
    {"sheen roughness 0.2 over a metal", [](Vec3 wo) { return sheen(wo, Vec3(0.9f), 1.0f, 0.2f); }},
    {"anisotropic metal, strength 0.8", [](Vec3 wo) { return anisotropic(wo, 0.8f); }},
    {"anisotropic metal, strength 1", [](Vec3 wo) { return anisotropic(wo, 1.0f); }},
    {"iridescent metal", [](Vec3 wo) { return iridescent(wo, 1.0f); }},
    {"iridescent dielectric", [](Vec3 wo) { return iridescent(wo, 0.0f); }},
    {"specular colour and factor", [](Vec3 wo) { return specular_colour(wo); }},
};

}  // namespace

TEST_CASE("BSDF sampling matches its density (chi-square over the sphere)", "[bsdf]") {
  for (const Case& c : kSmoothCases) {
    for (const float theta : {10.0f, 45.0f, 75.0f}) {
      const Bsdf bsdf(c.make(direction(theta, 30.0f)), c.eta);
      const ChiSquare test = chi_square(bsdf, 200000, 7);
      INFO(c.name << " at " << theta << " degrees: chi^2 = " << test.statistic << " over " << test.dof
                  << " cells, z = " << test.z << "; lost " << test.lost << " (expected " << test.expected_lost << ")");
      CHECK(test.dof > 20);
      CHECK(test.z < 4.0);  // p > 3e-5
      // Samples lost below the surface are the density's missing mass.
      CHECK(std::abs(test.lost - test.expected_lost) <
            5.0 * std::sqrt(std::max(test.expected_lost, 1.0)) + 0.002 * 200000);
    }
  }
}

TEST_CASE("BSDF: the density is positive wherever sampling goes, and weight = f cos / pdf", "[bsdf]") {
  for (const Case& c : kSmoothCases) {
    const Bsdf bsdf(c.make(direction(40.0f, 10.0f)), c.eta);
    Rng rng(3);
    int checked = 0;
    for (int k = 0; k < 20000; ++k) {
      BsdfSample s;
      if (!bsdf.sample(rng.next_float(), Vec2(rng.next_float(), rng.next_float()), s) || s.delta) continue;
      INFO(c.name);
      REQUIRE(bsdf.pdf(s.wi) > 0.0f);
      REQUIRE(s.pdf == Approx(bsdf.pdf(s.wi)).epsilon(1e-4));
      const Vec3 expected = bsdf.eval(s.wi) / s.pdf;
      REQUIRE(s.weight.x == Approx(expected.x).epsilon(1e-4).margin(1e-6));
      ++checked;
    }
    CHECK(checked > 12000);
  }
}

TEST_CASE("BSDF: f and its density together are the floats of each alone", "[bsdf]") {
  // eval(wi, pdf) shares the half vector, the microfacet density and Phong's power between the
  // two (multiple importance sampling asks for both): f must not move by a bit, over the whole
  // sphere, above and below the surface; the density it gives is the one sampling is tested on.
  int compared = 0;
  for (const Case& c : kSmoothCases) {
    const Bsdf bsdf(c.make(direction(35.0f, 20.0f)), c.eta);
    Rng rng(11);
    for (int k = 0; k < 2000; ++k) {
      const float z = 2.0f * rng.next_float() - 1.0f, phi = 2.0f * kPi * rng.next_float();
      const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      const Vec3 wi(r * std::cos(phi), r * std::sin(phi), z);
      float pdf = -1.0f;
      const Vec3 both = bsdf.eval(wi, pdf);
      const Vec3 alone = bsdf.eval(wi);
      INFO(c.name << ", direction " << k);
      REQUIRE(std::memcmp(&both, &alone, sizeof both) == 0);
      REQUIRE(pdf >= 0.0f);
      REQUIRE(pdf == bsdf.pdf(wi));
      ++compared;
    }
  }
  CHECK(compared == 2000 * static_cast<int>(std::size(kSmoothCases)));
}

TEST_CASE("BSDF: f is reciprocal, f(wo, wi) = f(wi, wo)", "[bsdf]") {
  Rng rng(11);
  for (const Case& c : kSmoothCases) {
    for (int k = 0; k < 200; ++k) {
      const Vec3 a = direction(85.0f * rng.next_float(), 360.0f * rng.next_float());
      const Vec3 b = direction(85.0f * rng.next_float(), 360.0f * rng.next_float());
      const Vec3 fab = Bsdf(c.make(a), c.eta).eval(b) / b.z;
      const Vec3 fba = Bsdf(c.make(b), c.eta).eval(a) / a.z;
      INFO(c.name);
      CHECK(fab.x == Approx(fba.x).epsilon(1e-3).margin(1e-6));
      CHECK(fab.z == Approx(fba.z).epsilon(1e-3).margin(1e-6));
    }
  }
}

TEST_CASE("BSDF: a white surface reflects at most what it receives", "[bsdf]") {
  for (const Case& c : kSmoothCases) {
    for (const float theta : {0.0f, 30.0f, 60.0f, 85.0f}) {
      const EvaluatedSurface s = c.make(direction(theta, 0.0f));
      const double a = albedo(Bsdf(s, c.eta));
      INFO(c.name << " at " << theta << " degrees: albedo " << a);
      // glTF's reference model is not strictly energy-conserving: its diffuse layer is weighted
      // by 1 - F(v.h) rather than by what the specular layer leaves, so a rough white dielectric
      // seen at grazing angles gives back a few percent more than it receives (1.051 at 85
      // degrees, roughness 0.6). The spec's model is kept as it is (docs/rendering.md).
      const bool gltf_dielectric = s.pbr && s.pbr->metallic < 1.0f && s.transmission_factor == 0.0f;
      CHECK(a <= (gltf_dielectric && theta > 60.0f ? 1.06 : 1.0 + 2e-3));
      if (theta <= 60.0f) CHECK(a > 0.3);  // at grazing angles a sharp lobe loses most of itself below the surface
    }
  }
  // Lambert of albedo 1 keeps everything; 0.5 half.
  CHECK(albedo(Bsdf(lambert(direction(30.0f, 0.0f), 1.0f), 1.0f)) == Approx(1.0).epsilon(2e-3));
  CHECK(albedo(Bsdf(lambert(direction(30.0f, 0.0f), 0.5f), 1.0f)) == Approx(0.5).epsilon(2e-3));
  // A Phong material whose weights add up to more than 1 is scaled down to 1.
  const double over = albedo(Bsdf(phong(direction(0.0f, 0.0f), 0.9f, 0.9f, 10.0f), 1.0f));
  CHECK(over <= 1.0 + 2e-3);
  CHECK(over > 0.9);
}

TEST_CASE("BSDF: delta lobes (mirror, glass) reflect and refract with their weights", "[bsdf]") {
  SECTION("a mirror of reflectivity 0.8 returns the mirror direction with weight 0.8") {
    EvaluatedSurface s = surface(direction(30.0f, 0.0f));
    s.reflectivity = Vec3(0.8f);
    const Bsdf bsdf(s, 1.0f);
    CHECK_FALSE(bsdf.has_smooth_lobes());
    BsdfSample out;
    REQUIRE(bsdf.sample(0.5f, Vec2(0.5f), out));
    CHECK(out.delta);
    CHECK(out.wi.x == Approx(-direction(30.0f, 0.0f).x));
    CHECK(out.wi.z == Approx(direction(30.0f, 0.0f).z));
    CHECK(out.weight.x == Approx(0.8f));
  }
  SECTION("a rough glTF surface of equal indices (BLEND's coverage) lets light straight through") {
    EvaluatedSurface s = metal_rough(direction(40.0f, 0.0f), Vec3(1.0f, 0.2f, 0.2f), 0.0f, 0.6f);
    s.transmission = Vec3(0.75f);
    s.transmission_factor = 0.75f;
    const Bsdf bsdf(s, 1.0f);
    CHECK(bsdf.lobe_probability(Bsdf::kRoughGlass) == 0.0f);
    REQUIRE(bsdf.lobe_probability(Bsdf::kGlass) > 0.0f);
    int through = 0;
    Rng rng(2);
    for (int k = 0; k < 2000; ++k) {
      BsdfSample out;
      if (!bsdf.sample(rng.next_float(), Vec2(rng.next_float(), rng.next_float()), out) || !out.transmitted) continue;
      ++through;
      CHECK(out.wi.x == Approx(-direction(40.0f, 0.0f).x).margin(1e-5));  // unbent
      CHECK(out.wi.z == Approx(-direction(40.0f, 0.0f).z).margin(1e-5));
    }
    CHECK(through > 500);
  }
  SECTION("glass of ior 1.5 reflects with the Fresnel probability and refracts by Snell's law") {
    EvaluatedSurface s = surface(direction(60.0f, 0.0f));
    s.transmission = Vec3(1.0f);
    const Bsdf bsdf(s, 1.5f);
    const float fresnel = fresnel_dielectric(std::cos(radians(60.0f)), 1.5f);
    // At 60 degrees: r_s^2 = 0.1766, r_p^2 = 0.0018, their mean 0.0892.
    CHECK(fresnel == Approx(0.0892).margin(2e-4));
    Rng rng(5);
    int reflected = 0;
    const int n = 100000;
    for (int k = 0; k < n; ++k) {
      BsdfSample out;
      REQUIRE(bsdf.sample(rng.next_float(), Vec2(0.5f), out));
      CHECK(out.weight.x == Approx(1.0f));
      if (out.transmitted) {
        // sin(theta_t) = sin(60) / 1.5
        CHECK(std::sqrt(1.0f - out.wi.z * out.wi.z) == Approx(std::sin(radians(60.0f)) / 1.5f).epsilon(1e-4));
        CHECK(out.wi.z < 0.0f);
      } else {
        ++reflected;
      }
    }
    CHECK(static_cast<double>(reflected) / n == Approx(fresnel).margin(4.0 * std::sqrt(fresnel / n)));
  }
}
