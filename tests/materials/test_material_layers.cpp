// The glTF layered extensions' building blocks with real numbers: the thin film's Fresnel
// (KHR_materials_iridescence), the sheen's albedo table (KHR_materials_sheen), dispersion's index
// and wavelength weights (KHR_materials_dispersion), and Whitted's approximation of them all.
#include <catch2/catch.hpp>

#include <cmath>

#include "materials/dispersion.h"
#include "materials/microfacet.h"
#include "materials/pbr_to_phong.h"
#include "materials/sheen.h"
#include "materials/thin_film.h"

using namespace rt;

TEST_CASE("Thin film: no film is the base's Schlick term, a film colours it", "[layers]") {
  // (Head-on only: at other angles the vanishing film's outer face keeps Schlick's (1 - cos)^5
  // of F0 = 0, as in the Khronos reference implementation.)
  for (const float cos_theta : {1.0f}) {
    const Vec3 base(0.04f, 0.5f, 0.9f);
    const Vec3 none = thin_film_fresnel(1.0f, 1.3f, cos_theta, 0.0f, base);
    const Vec3 schlick = schlick_fresnel(base, cos_theta);
    INFO("cos " << cos_theta);
    CHECK(none.x == Approx(schlick.x).margin(0.01));
    CHECK(none.y == Approx(schlick.y).margin(0.01));
    CHECK(none.z == Approx(schlick.z).margin(0.01));
  }

  // A 400 nm film of index 1.3 over a dielectric (F0 0.04) seen head-on: interference colours,
  // not a grey, every channel in [0, 1], and brighter than the bare dielectric on average (two
  // interfaces reflect).
  const Vec3 film = thin_film_fresnel(1.0f, 1.3f, 1.0f, 400.0f, Vec3(0.04f));
  CHECK(max_component(film) - std::min({film.x, film.y, film.z}) > 0.01f);
  CHECK(std::min({film.x, film.y, film.z}) >= 0.0f);
  CHECK(max_component(film) <= 1.0f);
  // The colour changes with thickness (the bands of a soap film).
  const Vec3 thicker = thin_film_fresnel(1.0f, 1.3f, 1.0f, 550.0f, Vec3(0.04f));
  CHECK(glm::length(thicker - film) > 0.01f);
  // Past the critical angle inside a film of lower index the film reflects everything.
  CHECK(thin_film_fresnel(1.5f, 1.0f, 0.2f, 300.0f, Vec3(0.04f)) == Vec3(1.0f));
}

TEST_CASE("Sheen: the albedo table matches the integral of its lobe", "[layers]") {
  // Direct integration of D V cos over the hemisphere, finer than the table's.
  const auto integral = [](float cos_v, float roughness) {
    const Vec3 wo(std::sqrt(1.0f - cos_v * cos_v), 0.0f, cos_v);
    constexpr int n = 256;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const float cos_l = (static_cast<float>(i) + 0.5f) / n, phi = 2.0f * kPi * (static_cast<float>(j) + 0.5f) / n;
        const float sin_l = std::sqrt(1.0f - cos_l * cos_l);
        const Vec3 wi(sin_l * std::cos(phi), sin_l * std::sin(phi), cos_l);
        const Vec3 h = glm::normalize(wi + wo);
        sum += sheen_distribution(roughness, h.z) * sheen_visibility(cos_l, cos_v, roughness) * cos_l;
      }
    return sum * 2.0 * kPi / (n * n);
  };
  for (const float roughness : {0.3f, 0.5f, 1.0f})
    for (const float cos_v : {0.2f, 0.5f, 0.9f}) {
      const double e = integral(cos_v, roughness);
      INFO("roughness " << roughness << ", cos " << cos_v << ": integral " << e);
      CHECK(sheen_albedo(cos_v, roughness) == Approx(e).margin(0.01));
      CHECK(e > 0.0);
      CHECK(e < 1.0);
    }
  // Charlie's D integrates to 1 over projected microfacet normals: int D cos_h dw = 1.
  for (const float roughness : {0.3f, 0.7f}) {
    constexpr int n = 2000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const float cos_h = (static_cast<float>(i) + 0.5f) / n;
      sum += sheen_distribution(roughness, cos_h) * cos_h * 2.0 * kPi / n;
    }
    CHECK(sum == Approx(1.0).epsilon(0.01));
  }
}

TEST_CASE("Dispersion: the index at the d line is the material's, and blue bends more", "[layers]") {
  CHECK(dispersed_ior(1.5f, 0.0f, 450.0f) == 1.5f);
  CHECK(dispersed_ior(1.5f, 1.0f, 587.56f) == Approx(1.5f).epsilon(1e-5));
  // dispersion 20 / V: V = 20 gives n_F - n_C = (n_d - 1) / V = 0.025.
  const float spread = dispersed_ior(1.5f, 1.0f, 486.13f) - dispersed_ior(1.5f, 1.0f, 656.27f);
  CHECK(spread == Approx(0.025f).epsilon(1e-3));
  CHECK(dispersed_ior(1.5f, 1.0f, 400.0f) > dispersed_ior(1.5f, 1.0f, 700.0f));
  // The wavelengths' colours average to white, and each is a colour of its part of the spectrum.
  Vec3 sum(0.0f);
  constexpr int n = 1000;
  for (int i = 0; i < n; ++i) sum += wavelength_weight(wavelength_from((static_cast<float>(i) + 0.5f) / n));
  CHECK(sum.x / n == Approx(1.0f).epsilon(0.01));
  CHECK(sum.y / n == Approx(1.0f).epsilon(0.01));
  CHECK(sum.z / n == Approx(1.0f).epsilon(0.01));
  const Vec3 red = wavelength_weight(650.0f), blue = wavelength_weight(450.0f), green = wavelength_weight(540.0f);
  CHECK(red.x > red.y);
  CHECK(red.x > red.z);
  CHECK(blue.z > blue.x);
  CHECK(blue.z > blue.y);
  CHECK(green.y > green.x);
  CHECK(green.y > green.z);
}

TEST_CASE("Whitted's approximation of the layers", "[layers]") {
  const Vec3 base(0.8f, 0.2f, 0.1f);
  const PhongTerms plain = pbr_to_phong(base, 0.0f, 0.6f);
  EvaluatedLayers none;
  const PhongTerms same = pbr_to_phong(base, 0.0f, 0.6f, none, 0.8f);
  CHECK(same.kd == plain.kd);
  CHECK(same.ks.x == Approx(plain.ks.x));
  CHECK(same.reflectivity.x == Approx(plain.reflectivity.x));
  SECTION("a smooth clear coat adds a sharp reflection and dims the base") {
    EvaluatedLayers coat;
    coat.clearcoat = 1.0f;
    const PhongTerms p = pbr_to_phong(base, 0.0f, 0.6f, coat, 1.0f);
    CHECK(p.kd.x == Approx(plain.kd.x * 0.96f));
    CHECK(p.reflectivity.x > plain.reflectivity.x + 0.03f);
    CHECK(p.glossy < plain.glossy);
  }
  SECTION("sheen brightens a dark base towards its colour") {
    EvaluatedLayers sheen;
    sheen.sheen_color = Vec3(0.0f, 0.0f, 1.0f);
    sheen.sheen_roughness = 0.5f;
    const PhongTerms p = pbr_to_phong(Vec3(0.0f), 0.0f, 0.6f, sheen, 0.5f);
    CHECK(p.kd.z > 0.05f);
    CHECK(p.kd.x == 0.0f);
  }
  SECTION("specular's colour and factor set the dielectric's F0") {
    EvaluatedLayers spec;
    spec.dielectric_f0 = Vec3(0.0f, 0.04f, 0.08f);
    const PhongTerms p = pbr_to_phong(base, 0.0f, 0.0f, spec, 1.0f);
    CHECK(p.ks.x == 0.0f);
    CHECK(p.ks.z == Approx(0.08f));
  }
}
