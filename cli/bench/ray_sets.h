// The rays `rtcli bench` traces, made (or read) before any clock starts, so that every tracer
// timed on them (rtcli's BVH, Embree in tools/embree_compare) sees exactly the same rays.
//  primary    - a pinhole camera framing the model at 1920x1080, one ray through each pixel centre;
//  incoherent - 2M rays from random points in a cube around the model (three times its size,
//               outside its box) towards random points inside its box: every ray enters the box,
//               no two go the same way;
//  occlusion  - from each primary hit towards a point light above the model, any-hit, tmax at
//               the light.
// A ray file (--save-rays / --rays) holds the sets as they are, so another program or another
// build replays them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/accel/primitives.h"
#include "core/ray.h"

namespace rt {

struct RaySet {
  std::string name;
  bool occlusion = false;  // any-hit (stop at the first blocker) rather than closest hit
  std::vector<Ray> rays;
};

inline constexpr int kPrimaryWidth = 1920, kPrimaryHeight = 1080;
inline constexpr size_t kIncoherentRays = 2'000'000;

// The three sets for `prims` (the occlusion set from a closest-hit pass over `prims`' BVH, which
// it builds: not part of any timing). Deterministic: the same model gives the same rays.
std::vector<RaySet> make_ray_sets(const PrimitiveSet& prims);

// Ray files: "RTRAYS01", the set count (uint32), then per set its name (uint8 length and bytes),
// its kind (uint8: 0 closest hit, 1 occlusion), its ray count (uint64) and its rays as eight
// float32 each (origin x y z, tmin, direction x y z, tmax), all little-endian. false and a
// reason in `error` on a file that cannot be written, or read back whole and sound.
bool write_ray_sets(const std::string& path, const std::vector<RaySet>& sets, std::string& error);
bool read_ray_sets(const std::string& path, std::vector<RaySet>& sets, std::string& error);

}  // namespace rt
