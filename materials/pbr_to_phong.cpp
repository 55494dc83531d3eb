#include "materials/pbr_to_phong.h"

#include "materials/microfacet.h"
#include "materials/sheen.h"
#include "materials/thin_film.h"

namespace rt {
namespace {

float average(Vec3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

}  // namespace

PhongTerms pbr_to_phong(Vec3 base_color, float metallic, float roughness, const EvaluatedLayers& l, float cos_view) {
  metallic = std::clamp(metallic, 0.0f, 1.0f);
  roughness = std::clamp(roughness, 0.0f, 1.0f);
  cos_view = std::clamp(cos_view, 0.0f, 1.0f);
  if (l.anisotropy > 0.0f) {
    const float alpha = roughness * roughness;
    const float along = alpha + (1.0f - alpha) * l.anisotropy * l.anisotropy;
    roughness = std::sqrt(std::sqrt(along * alpha));
  }
  PhongTerms p = pbr_to_phong(base_color, metallic, roughness);
  const float smooth = 1.0f - roughness;
  Vec3 dielectric = l.dielectric_f0, metal = base_color;
  if (l.iridescence > 0.0f) {
    dielectric =
        glm::mix(dielectric, thin_film_fresnel(1.0f, l.iridescence_ior, cos_view, l.iridescence_thickness, dielectric),
                 l.iridescence);
    metal = glm::mix(metal, thin_film_fresnel(1.0f, l.iridescence_ior, cos_view, l.iridescence_thickness, metal),
                     l.iridescence);
  }
  const Vec3 f0 = glm::mix(dielectric, metal, metallic);
  p.ks = f0 * smooth;
  p.reflectivity = f0 * (smooth * smooth);
  if (l.sheen_color != Vec3(0.0f)) {
    const float e = sheen_albedo(cos_view, l.sheen_roughness);
    const float keep = 1.0f - max_component(l.sheen_color) * e;
    p.kd = p.kd * keep + l.sheen_color * e;
    p.ks *= keep;
    p.reflectivity *= keep;
  }
  if (l.clearcoat > 0.0f) {
    const float coat = l.clearcoat * schlick_fresnel(Vec3(0.04f), cos_view).x;
    const float coat_smooth = 1.0f - std::clamp(l.clearcoat_roughness, 0.0f, 1.0f);
    const PhongTerms c = pbr_to_phong(Vec3(1.0f), 0.0f, l.clearcoat_roughness);
    const Vec3 coat_reflect(coat * coat_smooth * coat_smooth);
    const float share =
        average(coat_reflect) / std::max(average(coat_reflect) + average(p.reflectivity) * (1.0f - coat), 1e-6f);
    p.kd *= 1.0f - coat;
    p.ks = p.ks * (1.0f - coat) + Vec3(coat * coat_smooth);
    p.reflectivity = p.reflectivity * (1.0f - coat) + coat_reflect;
    p.glossy += (c.glossy - p.glossy) * share;
    p.shininess += (c.shininess - p.shininess) * share;
  }
  return p;
}

}  // namespace rt
