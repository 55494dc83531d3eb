// glTF's metallic-roughness model and its layered extensions in the path tracer's Bsdf (the
// lobes and their order: materials/bsdf.h).
#include "materials/bsdf.h"
#include "materials/optics.h"
#include "materials/sheen.h"
#include "materials/thin_film.h"

namespace rt {
namespace {

float average(Vec3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

float coat_fresnel(float cos_theta) { return dielectric_schlick(cos_theta); }  // F0 0.04: a coat of ior 1.5

}  // namespace

void Bsdf::init_gltf(const EvaluatedSurface& s, float cos_o, float* weight) {
  pbr_ = true;
  const PbrSurfaceTerms& p = *s.pbr;
  const EvaluatedLayers& l = p.layers;
  // s.transmission is already tinted by the base colour and none through metal; the opaque
  // layer keeps what the dielectric does not take.
  layer_ = 1.0f - std::clamp(s.transmission_factor, 0.0f, 1.0f);
  base_color_ = p.base_color;
  metallic_ = p.metallic;
  base_diffuse_ = (1.0f - p.metallic) * layer_ * p.base_color;
  f0_ = glm::mix(Vec3(0.04f), p.base_color, p.metallic);
  const float alpha = p.roughness * p.roughness;
  // KHR_materials_anisotropy: rougher along the direction (the frame's x), alpha across it.
  const float along = alpha + (1.0f - alpha) * l.anisotropy * l.anisotropy;
  ggx_ = Ggx(l.anisotropy > 0.0f ? along : alpha, alpha);
  ggx_g1_wo_ = ggx_.g1(wo_local_);
  glass_ggx_ = Ggx(alpha);
  general_fresnel_ = !l.default_fresnel();
  dielectric_f0_ = l.dielectric_f0;
  dielectric_f90_ = l.dielectric_f90;
  iridescence_ = l.iridescence;
  iridescence_ior_ = l.iridescence_ior;
  iridescence_thickness_ = l.iridescence_thickness;

  // What the layers on top let through to the base, as seen from wo.
  if (l.sheen_color != Vec3(0.0f)) {
    sheen_color_ = l.sheen_color;
    sheen_roughness_ = l.sheen_roughness;
    sheen_max_ = max_component(l.sheen_color);
    sheen_keep_o_ = 1.0f - sheen_max_ * sheen_albedo(cos_o, sheen_roughness_);
  }
  if (l.clearcoat > 0.0f) {
    coat_ = l.clearcoat;
    coat_frame_ = ShadingFrame(l.clearcoat_n);
    coat_wo_ = coat_frame_.to_local(s.wo);
    coat_ggx_ = Ggx(l.clearcoat_roughness * l.clearcoat_roughness);
    coat_mirror_ = coat_ggx_.alpha_x < kSmoothAlpha;
    coat_keep_ = 1.0f - coat_ * coat_fresnel(std::max(coat_wo_.z, 0.0f));
  }
  const float keep = coat_keep_ * sheen_keep_o_;

  Vec3 dielectric;
  const Vec3 fresnel = layer_ * gltf_fresnel(cos_o, dielectric);
  weight[kDiffuse] = keep * average(base_diffuse_ * (Vec3(1.0f) - dielectric));
  if (std::max(ggx_.alpha_x, ggx_.alpha_y) < kSmoothAlpha) {
    mirror_ = keep * fresnel;
    weight[kMirror] = average(mirror_);
  } else {
    weight[kSpecular] = keep * average(fresnel);
  }
  glass_reflect_ = Vec3(keep * (1.0f - layer_));
  glass_refract_ = keep * s.transmission;
  // Rough transmission is a GGX dielectric of the same roughness; a smooth one a delta, and so
  // is an interface of equal indices (BLEND's coverage), through which light passes straight.
  const bool smooth_glass = alpha < kSmoothAlpha || eta_ == 1.0f;
  weight[smooth_glass ? kGlass : kRoughGlass] = average(glass_reflect_ + glass_refract_) * 0.5f;
  if (coat_ > 0.0f) weight[kClearcoat] = coat_ * coat_fresnel(std::max(coat_wo_.z, 0.0f));
  if (sheen_max_ > 0.0f) weight[kSheen] = coat_keep_ * sheen_max_ * sheen_albedo(cos_o, sheen_roughness_);
}

// The core model's Schlick inline (the common case, at every light's direction); the layers'
// general form out of line, so that this stays small enough to be inlined.
inline Vec3 Bsdf::gltf_fresnel(float cos_h, Vec3& dielectric) const {
  if (general_fresnel_) return layered_fresnel(cos_h, dielectric);
  dielectric = Vec3(dielectric_schlick(cos_h));
  return schlick_fresnel(f0_, cos_h);
}

Vec3 Bsdf::layered_fresnel(float cos_h, Vec3& dielectric) const {
  const float m = std::clamp(1.0f - cos_h, 0.0f, 1.0f);
  const float m5 = (m * m) * (m * m) * m;
  dielectric = dielectric_f0_ + (Vec3(dielectric_f90_) - dielectric_f0_) * m5;
  Vec3 metal = base_color_ + (Vec3(1.0f) - base_color_) * m5;
  if (iridescence_ > 0.0f) {
    const Vec3 film_d = thin_film_fresnel(1.0f, iridescence_ior_, cos_h, iridescence_thickness_, dielectric_f0_);
    const Vec3 film_m = thin_film_fresnel(1.0f, iridescence_ior_, cos_h, iridescence_thickness_, base_color_);
    dielectric = glm::mix(dielectric, film_d, iridescence_);
    metal = glm::mix(metal, film_m, iridescence_);
  }
  return glm::mix(dielectric, metal, metallic_);
}

Vec3 Bsdf::coat_f(Vec3 wi) const {
  if (!(probability_[kClearcoat] > 0.0f) || coat_mirror_) return Vec3(0.0f);
  const Vec3 wo = coat_wo_, w = coat_frame_.to_local(wi);
  if (w.z <= 0.0f || wo.z <= 0.0f) return Vec3(0.0f);
  const Vec3 h = glm::normalize(wo + w);
  const float f = coat_ * coat_fresnel(std::max(glm::dot(wo, h), 0.0f)) * coat_ggx_.d(h) * coat_ggx_.g1(w) *
                  coat_ggx_.g1(wo) / (4.0f * wo.z);
  return Vec3(f);
}

float Bsdf::coat_pdf(Vec3 wi) const {
  if (!(probability_[kClearcoat] > 0.0f) || coat_mirror_) return 0.0f;
  const Vec3 w = coat_frame_.to_local(wi);
  if (w.z <= 0.0f || coat_wo_.z <= 0.0f) return 0.0f;
  return probability_[kClearcoat] * coat_ggx_.reflected_pdf(coat_wo_, glm::normalize(coat_wo_ + w));
}

Vec3 Bsdf::eval_gltf(Vec3 wi_world, Vec3 wi, float* pdf) const {
  const Vec3 wo = wo_local_;
  Vec3 f(0.0f);
  float density = 0.0f;
  if (coat_ > 0.0f) {
    f = coat_f(wi_world);
    if (pdf) density = coat_pdf(wi_world);
  }
  if (probability_[kRoughGlass] > 0.0f) {
    Vec3 glass;
    float glass_pdf;
    rough_glass(wi, glass, glass_pdf);
    f += glass;  // (weighted by what the layers above let through, seen from wo)
    density += glass_pdf * probability_[kRoughGlass];
  }
  if (pdf) *pdf = density;
  if (wi.z <= 0.0f || wo.z <= 0.0f) return f;
  const Vec3 h = glm::normalize(wo + wi);
  const float wo_h = std::max(glm::dot(wo, h), 0.0f);
  Vec3 dielectric;
  const Vec3 fresnel = gltf_fresnel(wo_h, dielectric);
  Vec3 base = base_diffuse_ * (Vec3(1.0f) - dielectric) * (wi.z / kPi);
  density += (probability_[kDiffuse] + probability_[kSheen]) * wi.z / kPi;
  if (probability_[kSpecular] > 0.0f) {
    const float d = ggx_.d(h);
    base += layer_ * fresnel * (d * ggx_.g1(wi) * ggx_g1_wo_ / (4.0f * wo.z));
    // Drawn by the visible normals: G1(wo) D(h) / (4 wo.z) (Ggx::reflected_pdf; wo.z > 0 here).
    density += probability_[kSpecular] * (ggx_g1_wo_ * d / (4.0f * wo.z));
  }
  if (pdf) *pdf = density;
  if (sheen_max_ > 0.0f) {
    // The base keeps what the sheen leaves on the way in and out (the smaller share: reciprocal).
    base *= std::min(sheen_keep_o_, 1.0f - sheen_max_ * sheen_albedo(wi.z, sheen_roughness_));
    base += sheen_color_ *
            (sheen_distribution(sheen_roughness_, h.z) * sheen_visibility(wi.z, wo.z, sheen_roughness_) * wi.z);
  }
  float keep = coat_keep_;  // likewise under the coat
  if (coat_ > 0.0f)
    keep = std::min(keep, 1.0f - coat_ * coat_fresnel(std::max(coat_frame_.to_local(wi_world).z, 0.0f)));
  return f + keep * base;
}

// A direction (world) from the clear coat's rough lobe or the sheen's (cosine-distributed: the
// sheen is broad, and its density is the cosine's in eval_gltf).
bool Bsdf::sample_gltf_lobe(Lobe lobe, Vec2 u, Vec3& wi) const {
  if (lobe == kSheen) {
    wi = frame_.to_world(cosine_hemisphere(u));
    return true;
  }
  if (coat_wo_.z <= 0.0f) return false;
  const Vec3 h = coat_ggx_.sample_visible(coat_wo_, u);
  wi = coat_frame_.to_world(reflect(-coat_wo_, h));
  return true;
}

}  // namespace rt
