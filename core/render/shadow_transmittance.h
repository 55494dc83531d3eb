// Shadow rays through glass.
#pragma once

#include "core/scene.h"

namespace rt {

// The fraction of light that passes along a shadow ray, per channel: 0 when anything opaque is
// in the way; otherwise, for every transmissive surface crossed, a filter of its transmission
// times 1 - F0, F0 = ((n - 1) / (n + 1))^2 its Fresnel reflectance at normal incidence, times
// Beer-Lambert absorption over the distance inside each absorbing object. So glass casts a
// light, tinted shadow all over (a clear sphere of n = 1.5, two surfaces: 0.92), as POV-Ray's
// filter does. Shadow rays are not bent (no caustics), so the angle at which one meets a surface
// means nothing physical: Fresnel at that angle made the unbent ray meet total internal
// reflection on the way out, and a glass sphere's shadow had a black outer ring. Any-hit
// traversal with a visitor: it stops at the first opaque surface.
// In a scene without transmissive materials (Scene::all_opaque): the occlusion kernel alone, which
// gives the same answer. `among`: the leaves of the BVH that a volume holding the ray reaches
// (Bvh::leaves_meeting), when known: none, and nothing is in the way; one, and only its
// crossings are visited (the same as the walk's); more, and the walk finds them.
Vec3 shadow_transmittance(const Scene& scene, const Ray& ray, const BvhLeafSet* among = nullptr);

}  // namespace rt
