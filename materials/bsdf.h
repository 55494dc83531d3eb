// The path tracer's scattering model at one shading point: a fixed set of lobes built from the
// evaluated surface, each of which can be evaluated, sampled and give its density. One model for
// both material kinds (docs/rendering.md, "Path tracing: materials"):
//   Phong material                       glTF metallic-roughness material
//   diffuse  kd x (1 - T): Lambert        (1 - metallic)(1 - F(0.04)) base / pi: Lambert
//   specular ks: a Phong lobe             F(mix(0.04, base, metallic)) D G / (4 cos cos): GGX
//   reflectivity: a mirror (delta), or with glossy width a a Phong lobe of exponent 12 / a^2
//   transmission T: smooth dielectric (delta), Fresnel-split into reflection and refraction;
//                  glTF's with roughness: a rough GGX dielectric (Walter et al. 2007)
// glTF's layered extensions (materials/bsdf_gltf.cpp; docs/rendering.md, "glTF material extensions"):
//   specular, ior  the dielectric's F = F0 + (F90 - F0)(1 - v.h)^5, F0 and F90 given per point
//   iridescence    F mixed with the thin film's reflectance (materials/thin_film.h) by its factor
//   anisotropy     the GGX lobe with alpha_t along the direction and alpha across it
//   sheen          + Charlie sheen (materials/sheen.h); the rest x (1 - max(colour) E(cos)), the
//                  smaller of the view's and the light's
//   clearcoat      + a GGX layer of F0 0.04 about its own normal (a mirror when smooth); the rest
//                  x (1 - clearcoat F_coat(n_coat.v)), the smaller of the view's and the light's
//                  (the specification attenuates by the view's alone; both keep f reciprocal)
// A Phong material whose weights add up to more than 1 in a channel is scaled down to 1, so that
// no surface gives back more light than it receives. No virtual calls, nothing allocated.
#pragma once

#include "core/direction_sampling.h"
#include "materials/evaluated_surface.h"
#include "materials/microfacet.h"

namespace rt {

struct BsdfSample {
  Vec3 wi{0.0f};      // unit, world space, away from the surface
  Vec3 weight{0.0f};  // f |cos| / pdf: what the path's throughput is multiplied by
  float pdf = 0.0f;   // per unit solid angle for a smooth lobe; the lobe's probability for a delta lobe
  bool delta = false;
  bool transmitted = false;  // wi goes through the surface
};

class Bsdf {
 public:
  // (kClearcoat and kSheen come before kRoughGlass so that, without them, a lobe is picked from
  // the same numbers as before they existed.)
  enum Lobe { kDiffuse, kSpecular, kGlossy, kMirror, kGlass, kClearcoat, kSheen, kRoughGlass, kLobeCount };

  // `eta` is the index of refraction past the surface over the index on the ray's side (for
  // transmission; 1 when the surface lets nothing through).
  Bsdf(const EvaluatedSurface& s, float eta);

  // Whether any lobe is smooth (not a delta): only then is light sampling worth a shadow ray.
  bool has_smooth_lobes() const { return smooth_; }
  // f(wo, wi) |n.wi| summed over the smooth lobes, for wi in world space (through the surface
  // too, for a rough dielectric).
  Vec3 eval(Vec3 wi) const;
  // The density with which sample() returns wi through a smooth lobe.
  float pdf(Vec3 wi) const;
  // Both at once (multiple importance sampling wants both): the same floats, with the work they
  // share (the half vector, its microfacet density, Phong's power) done once.
  Vec3 eval(Vec3 wi, float& pdf) const;
  // A direction from the lobes, picked by u_lobe; u places it within its lobe. False: the
  // sample was lost (below the surface), contributing nothing.
  bool sample(float u_lobe, Vec2 u, BsdfSample& out) const;

  // The probability of picking each lobe (sums to 1 when any lobe has weight).
  float lobe_probability(Lobe lobe) const { return probability_[lobe]; }

 private:
  // glTF's model: its lobes' weights at wo (the constructor's share).
  void init_gltf(const EvaluatedSurface& s, float cos_o, float* weight);
  // The specular lobe's Fresnel at cos(v.h), and the dielectric's part of it (for the diffuse
  // layer under it).
  Vec3 gltf_fresnel(float cos_h, Vec3& dielectric) const;
  Vec3 layered_fresnel(float cos_h, Vec3& dielectric) const;  // its general_fresnel_ case, out of line
  Vec3 eval_gltf(Vec3 wi, Vec3 wi_local, float* pdf) const;
  // The clear coat's f |cos| and density at wi (world), 0 when it is a mirror (or there is no
  // coat: coat_ 0, which callers test first, as most materials have none).
  Vec3 coat_f(Vec3 wi) const;
  float coat_pdf(Vec3 wi) const;
  bool sample_gltf_lobe(Lobe lobe, Vec2 u, Vec3& wi) const;
  // f |cos| at wi (world) and wi_local (the lobes' frame), and where `pdf` is given the density
  // of drawing wi there too.
  Vec3 eval_local(Vec3 wi, Vec3 wi_local, float* pdf) const;
  // The rough dielectric's f |cos| and its density (with its own reflect / refract split) at wi.
  void rough_glass(Vec3 wi, Vec3& f, float& pdf) const;
  bool sides_agree(Vec3 wi, Vec3 wi_local) const;

  ShadingFrame frame_;
  Vec3 ng_{0.0f};  // geometric normal, on wo's side
  Vec3 wo_local_{0.0f};
  // Phong lobes
  Vec3 diffuse_{0.0f};
  Vec3 specular_{0.0f};
  float specular_exponent_ = 1.0f;
  Vec3 glossy_{0.0f};
  float glossy_exponent_ = 1.0f;
  Vec3 mirror_{0.0f};
  // the dielectric: reflection and refraction weights, relative index
  Vec3 glass_reflect_{0.0f}, glass_refract_{0.0f};
  float eta_ = 1.0f;
  // glTF's model (replaces the diffuse and specular lobes above when pbr_)
  bool pbr_ = false;
  Vec3 base_diffuse_{0.0f};  // (1 - metallic)(1 - transmission) base
  Vec3 f0_{0.04f};
  float layer_ = 1.0f;  // 1 - transmission: what the opaque layer keeps
  Vec3 base_color_{0.0f};
  float metallic_ = 0.0f;
  Ggx ggx_;                 // the specular lobe's (anisotropic with KHR_materials_anisotropy)
  float ggx_g1_wo_ = 0.0f;  // its masking of wo: the same for every light's direction, so once
  Ggx glass_ggx_;           // the rough dielectric's
  // the layered extensions (EvaluatedLayers)
  bool general_fresnel_ = false;  // F0, F90 or iridescence other than the core model's
  Vec3 dielectric_f0_{0.04f};
  float dielectric_f90_ = 1.0f;
  float iridescence_ = 0.0f, iridescence_ior_ = 1.3f, iridescence_thickness_ = 0.0f;
  float coat_ = 0.0f;  // the clearcoat factor
  bool coat_mirror_ = false;
  Vec3 coat_wo_{0.0f, 0.0f, 1.0f};  // wo in the coat's frame
  ShadingFrame coat_frame_;
  Ggx coat_ggx_;
  float coat_keep_ = 1.0f;  // 1 - coat F_coat(n_coat.v): what passes to the layers below
  Vec3 sheen_color_{0.0f};
  float sheen_roughness_ = 0.0f, sheen_max_ = 0.0f;
  float sheen_keep_o_ = 1.0f;  // 1 - max(colour) E(n.v)
  float probability_[kLobeCount] = {};
  bool smooth_ = false;
};

// The Phong lobe's exponent for the proposal's glossy width a (a blur square of side a about the
// mirror direction has an angular variance of a^2 / 12 per axis, as cos^n has 1 / n).
inline float glossy_exponent(float width) { return std::clamp(12.0f / (width * width), 1.0f, 1e6f); }

}  // namespace rt
