// KHR_materials_sheen's microfibre lobe, as the glTF specification and the Khronos sample viewer
// define it: the "Charlie" distribution (Estevez and Kulla, "Production Friendly Microfacet Sheen
// BRDF", 2017) with its fitted visibility term, and the lobe's directional albedo, by which the
// layer under the sheen is dimmed. `roughness` is sheenRoughness (alpha = roughness^2), cosines are
// with the shading normal.
#pragma once

namespace rt {

// D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi).
float sheen_distribution(float roughness, float cos_h);
// Estevez and Kulla's visibility, 1 / ((1 + Lambda(v) + Lambda(l)) 4 cos_l cos_v), clamped to [0, 1].
float sheen_visibility(float cos_l, float cos_v, float roughness);
// The lobe's albedo for a white sheen seen at cos_v: the integral of D V cos_l over the
// hemisphere, interpolated in a table integrated once (32 x 32 over cos_v and roughness).
float sheen_albedo(float cos_v, float roughness);

}  // namespace rt
