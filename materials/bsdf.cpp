#include "materials/bsdf.h"

#include "materials/lobe_power.h"
#include "materials/optics.h"

namespace rt {
namespace {

float average(Vec3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

// The Phong lobe about the mirror direction r (local), as f: (n + 1) / (2 pi) cos^n(alpha) /
// max(cos theta_i, cos theta_o). The density of the lobe over the larger cosine (Ashikhmin and
// Shirley's denominator) keeps it reciprocal, gives back at most ks at every angle and close to ks
// wherever the lobe stays above the surface; the classic normalisation, (n + 2) / (2 pi) cos^n,
// gives back only about ks cos(theta_o), so glossy rims went dark.
// The normalised Phong lobe about r: the density sample_phong draws wi with. eval_local's
// f |cos| is this / max(cos wi, cos wo) x cos wi.
float phong_pdf(Vec3 wi, Vec3 r, float exponent) {
  const float c = glm::dot(wi, r);
  return c > 0.0f ? (exponent + 1.0f) * (0.5f / kPi) * lobe_power(c, exponent) : 0.0f;
}
Vec3 sample_phong(Vec3 r, float exponent, Vec2 u) {
  const float cos_a = std::pow(u.x, 1.0f / (exponent + 1.0f));
  const float sin_a = std::sqrt(std::max(0.0f, 1.0f - cos_a * cos_a));
  const float phi = 2.0f * kPi * u.y;
  return ShadingFrame(r).to_world(Vec3(sin_a * std::cos(phi), sin_a * std::sin(phi), cos_a));
}

Vec3 mirror_local(Vec3 wo) { return Vec3(-wo.x, -wo.y, wo.z); }

// The frame of the lobes: about the shading normal, its x axis along an anisotropic lobe's direction.
ShadingFrame lobe_frame(const EvaluatedSurface& s) {
  return s.pbr && s.pbr->layers.anisotropy > 0.0f ? ShadingFrame(s.n, s.pbr->layers.anisotropy_direction)
                                                  : ShadingFrame(s.n);
}

}  // namespace

Bsdf::Bsdf(const EvaluatedSurface& s, float eta) : frame_(lobe_frame(s)), ng_(s.ng), eta_(eta) {
  wo_local_ = frame_.to_local(s.wo);
  const float cos_o = std::max(wo_local_.z, 0.0f);
  float weight[kLobeCount] = {};
  if (s.pbr) {
    init_gltf(s, cos_o, weight);
  } else {
    // The transmitted share T goes to the dielectric; the opaque lobes share what is left.
    const Vec3 opaque = Vec3(1.0f) - s.transmission;
    diffuse_ = s.diffuse;  // kd (1 - T) already
    specular_ = s.specular * opaque;
    specular_exponent_ = std::max(s.shininess, 0.0f);
    const Vec3 reflect = s.reflectivity * opaque;
    if (s.glossy > 0.0f) {
      glossy_ = reflect;
      glossy_exponent_ = glossy_exponent(s.glossy);
    } else {
      mirror_ = reflect;
    }
    glass_reflect_ = glass_refract_ = s.transmission;
    const float total = max_component(diffuse_ + specular_ + reflect + s.transmission);
    if (total > 1.0f) {
      const float scale = 1.0f / total;
      diffuse_ *= scale;
      specular_ *= scale;
      glossy_ *= scale;
      mirror_ *= scale;
      glass_reflect_ *= scale;
      glass_refract_ *= scale;
    }
    weight[kDiffuse] = average(diffuse_);
    weight[kSpecular] = average(specular_);
    weight[kGlossy] = average(glossy_);
    weight[kMirror] = average(mirror_);
    weight[kGlass] = average(glass_reflect_);
  }
  float sum = 0.0f;
  for (const float w : weight) sum += w;
  // Only the lobes present divide (a Phong surface has one or two of eight): an absent lobe's
  // probability stays 0, as 0 / sum would make it.
  if (sum > 0.0f)
    for (int i = 0; i < kLobeCount; ++i)
      if (weight[i] != 0.0f) probability_[i] = weight[i] / sum;
  smooth_ = probability_[kDiffuse] > 0.0f || probability_[kSpecular] > 0.0f || probability_[kGlossy] > 0.0f ||
            probability_[kRoughGlass] > 0.0f || probability_[kSheen] > 0.0f ||
            (probability_[kClearcoat] > 0.0f && !coat_mirror_);
}

// pbrt-v4's rough dielectric (DielectricBxDF), after Walter et al., "Microfacet Models for
// Refraction through Rough Surfaces" (2007): the microfacet normal wm from wo and wi (the
// generalised half vector), Fresnel at wo.wm splitting reflection from refraction, Smith's
// separable masking of both directions, and the density of drawing wm by the visible normals,
// carried to wi by the reflection's or refraction's Jacobian. Radiance is not scaled by 1 / eta^2
// across the interface (nor is it for the smooth dielectric): a path into and out of glass
// takes both factors, which cancel.
void Bsdf::rough_glass(Vec3 wi, Vec3& f, float& pdf) const {
  f = Vec3(0.0f);
  pdf = 0.0f;
  const Vec3 wo = wo_local_;
  if (wo.z <= 0.0f || wi.z == 0.0f) return;
  const bool reflect = wi.z > 0.0f;
  const float etap = reflect ? 1.0f : eta_;
  Vec3 wm = wi * etap + wo;
  if (glm::dot(wm, wm) <= 0.0f) return;
  wm = glm::normalize(wm);
  if (wm.z < 0.0f) wm = -wm;
  const float wo_m = glm::dot(wo, wm), wi_m = glm::dot(wi, wm);
  if (wo_m <= 0.0f || wi_m * wi.z < 0.0f) return;  // a microfacet seen from behind
  const float fresnel = fresnel_dielectric(wo_m, eta_);
  const float d = glass_ggx_.d(wm);
  const Vec3 wi_up(wi.x, wi.y, std::fabs(wi.z));
  const float g = glass_ggx_.g1(wo) * glass_ggx_.g1(wi_up);
  const float visible = glass_ggx_.g1(wo) * d * wo_m / wo.z;  // the density of drawing wm from wo
  if (reflect) {
    f = glass_reflect_ * (d * g * fresnel / (4.0f * wo.z));
    pdf = visible / (4.0f * wo_m) * fresnel;
  } else {
    const float denom = (wi_m + wo_m / etap) * (wi_m + wo_m / etap);
    if (!(denom > 0.0f)) return;
    f = glass_refract_ * (d * g * (1.0f - fresnel) * std::fabs(wi_m * wo_m / (wo.z * denom)));
    pdf = visible * std::fabs(wi_m) / denom * (1.0f - fresnel);
  }
}

Vec3 Bsdf::eval_local(Vec3 wi_world, Vec3 wi, float* pdf) const {
  if (pbr_) return eval_gltf(wi_world, wi, pdf);
  const Vec3 wo = wo_local_;
  if (pdf) *pdf = 0.0f;
  if (wi.z <= 0.0f || wo.z <= 0.0f) return Vec3(0.0f);
  const Vec3 r = mirror_local(wo);
  Vec3 f = diffuse_ * (wi.z / kPi);
  float density = probability_[kDiffuse] * wi.z / kPi;
  // Each Phong lobe's power once, for its f and its density.
  const auto lobe = [&](Lobe l, Vec3 colour, float exponent) {
    if (!(probability_[l] > 0.0f)) return;
    const float lobe_pdf = phong_pdf(wi, r, exponent);
    f += colour * (lobe_pdf / std::max(wi.z, wo.z) * wi.z);
    density += probability_[l] * lobe_pdf;
  };
  lobe(kSpecular, specular_, specular_exponent_);
  lobe(kGlossy, glossy_, glossy_exponent_);
  if (pdf) *pdf = density;
  return f;
}

// wi must be on the same side of the geometric surface as of the shading one: a shading normal
// tilted from the geometric one would otherwise let light leak through or reflect from inside.
bool Bsdf::sides_agree(Vec3 wi, Vec3 wi_local) const {
  const float geometric = glm::dot(wi, ng_);
  if (geometric == 0.0f || wi_local.z == 0.0f) return false;
  if ((geometric > 0.0f) != (wi_local.z > 0.0f)) return false;
  return geometric > 0.0f || probability_[kRoughGlass] > 0.0f;  // only the rough dielectric lets light through
}

Vec3 Bsdf::eval(Vec3 wi) const {
  if (!smooth_) return Vec3(0.0f);
  const Vec3 local = frame_.to_local(wi);
  return sides_agree(wi, local) ? eval_local(wi, local, nullptr) : Vec3(0.0f);
}

float Bsdf::pdf(Vec3 wi) const {
  float density = 0.0f;
  eval(wi, density);
  return density;
}

Vec3 Bsdf::eval(Vec3 wi, float& pdf) const {
  pdf = 0.0f;
  if (!smooth_) return Vec3(0.0f);
  const Vec3 local = frame_.to_local(wi);
  return sides_agree(wi, local) ? eval_local(wi, local, &pdf) : Vec3(0.0f);
}

bool Bsdf::sample(float u_lobe, Vec2 u, BsdfSample& out) const {
  int lobe = 0;
  float below = 0.0f;  // the probability of the lobes before `lobe`
  for (; lobe < kLobeCount - 1; ++lobe) {
    if (u_lobe < below + probability_[lobe]) break;
    below += probability_[lobe];
  }
  const float p = probability_[lobe];
  if (p <= 0.0f) return false;
  const Vec3 wo = frame_.to_world(wo_local_);
  out = BsdfSample{};
  if (lobe == kClearcoat && coat_mirror_) {  // a smooth coat: the mirror about its own normal
    Vec3 mirror = reflect(-wo, coat_frame_.n);
    if (glm::dot(mirror, ng_) <= 0.0f) mirror = reflect(-wo, ng_);
    out.delta = true;
    out.wi = mirror;
    out.weight = Vec3(coat_ * schlick_fresnel(Vec3(0.04f), coat_wo_.z).x / p);
    out.pdf = p;
    return true;
  }
  if (lobe == kMirror || lobe == kGlass) {
    out.delta = true;
    Vec3 mirror = reflect(-wo, frame_.n);
    if (glm::dot(mirror, ng_) <= 0.0f) mirror = reflect(-wo, ng_);  // never into the surface
    if (lobe == kMirror) {
      out.wi = mirror;
      out.weight = mirror_ / p;
      out.pdf = p;
      return true;
    }
    // The dielectric: reflect with the Fresnel probability, else refract (u_lobe's remainder
    // within the lobe decides, so that no other number is needed).
    const float fresnel = fresnel_dielectric(wo_local_.z, eta_);
    const float within = (u_lobe - below) / p;
    if (within < fresnel) {
      out.wi = mirror;
      out.weight = glass_reflect_ / p;
      out.pdf = p * fresnel;
      return true;
    }
    Vec3 refracted;
    if (!refract(-wo, frame_.n, 1.0f / eta_, refracted) || glm::dot(refracted, ng_) >= 0.0f) {
      if (!refract(-wo, ng_, 1.0f / eta_, refracted)) return false;
    }
    out.wi = refracted;
    out.weight = glass_refract_ / p;
    out.pdf = p * (1.0f - fresnel);
    out.transmitted = true;
    return true;
  }
  Vec3 wi_local, wi;
  if (lobe == kClearcoat || lobe == kSheen) {
    if (!sample_gltf_lobe(static_cast<Lobe>(lobe), u, wi)) return false;
    wi_local = frame_.to_local(wi);
  } else if (lobe == kRoughGlass) {
    if (wo_local_.z <= 0.0f) return false;
    const Vec3 h = glass_ggx_.sample_visible(wo_local_, u);
    const float fresnel = fresnel_dielectric(glm::dot(wo_local_, h), eta_);
    // A reflection must stay above the surface and a refraction go below it: the other way
    // round it is a direction whose density belongs to the other branch.
    if ((u_lobe - below) / p < fresnel) {
      wi_local = reflect(-wo_local_, h);
      if (wi_local.z <= 0.0f) return false;
    } else if (!refract(-wo_local_, h, 1.0f / eta_, wi_local) || wi_local.z >= 0.0f) {
      return false;
    }
  } else if (lobe == kDiffuse) {
    wi_local = cosine_hemisphere(u);
  } else if (pbr_) {
    if (wo_local_.z <= 0.0f) return false;
    const Vec3 h = ggx_.sample_visible(wo_local_, u);
    wi_local = reflect(-wo_local_, h);
  } else {
    const float exponent = lobe == kSpecular ? specular_exponent_ : glossy_exponent_;
    wi_local = sample_phong(mirror_local(wo_local_), exponent, u);
  }
  if (lobe != kClearcoat && lobe != kSheen) wi = frame_.to_world(wi_local);
  if (!sides_agree(wi, wi_local)) return false;
  float density = 0.0f;
  const Vec3 f = eval_local(wi, wi_local, &density);
  if (!(density > 0.0f)) return false;
  out.wi = wi;
  out.pdf = density;
  out.weight = f / density;
  out.transmitted = wi_local.z < 0.0f;
  return true;
}

}  // namespace rt
