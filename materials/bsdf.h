// The path tracer's scattering model at one shading point: a fixed set of lobes built from the
// evaluated surface, each of which can be evaluated, sampled and give its density. One model for
// both material kinds (docs/rendering.md, "Path tracing: materials"):
//   Phong material                       glTF metallic-roughness material
//   diffuse  kd x (1 - T): Lambert        (1 - metallic)(1 - F(0.04)) base / pi: Lambert
//   specular ks: a Phong lobe             F(mix(0.04, base, metallic)) D G / (4 cos cos): GGX
//   reflectivity: a mirror (delta), or with glossy width a a Phong lobe of exponent 12 / a^2
//   transmission T: smooth dielectric (delta), Fresnel-split into reflection and refraction;
//                  glTF's with roughness: a rough GGX dielectric (Walter et al. 2007)
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
  enum Lobe { kDiffuse, kSpecular, kGlossy, kMirror, kGlass, kRoughGlass, kLobeCount };

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
  // A direction from the lobes, picked by u_lobe; u places it within its lobe. False: the
  // sample was lost (below the surface), contributing nothing.
  bool sample(float u_lobe, Vec2 u, BsdfSample& out) const;

  // The probability of picking each lobe (sums to 1 when any lobe has weight).
  float lobe_probability(Lobe lobe) const { return probability_[lobe]; }

 private:
  Vec3 eval_local(Vec3 wi_local) const;
  float pdf_local(Vec3 wi_local) const;
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
  Ggx ggx_;
  float probability_[kLobeCount] = {};
  bool smooth_ = false;
};

// The Phong lobe's exponent for the proposal's glossy width a (a blur square of side a about the
// mirror direction has an angular variance of a^2 / 12 per axis, as cos^n has 1 / n).
inline float glossy_exponent(float width) { return std::clamp(12.0f / (width * width), 1.0f, 1e6f); }

}  // namespace rt
