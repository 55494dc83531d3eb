// Keyframed animation of one part of one node's transform, as glTF animation channels and the
// scene format's "animation" tracks describe it. Sampling between keys: step holds the earlier
// key; linear interpolates (rotations by spherical linear interpolation, the short way round);
// cubic spline is glTF's Hermite spline with in- and out-tangents per key (rotations
// renormalised). Before the first key the first value holds, after the last key the last.
#pragma once

#include <cstdint>
#include <vector>

#include "core/animation/trs.h"

namespace rt {

enum class TrsPart : uint8_t { kTranslation, kRotation, kScale };
enum class Interpolation : uint8_t { kStep, kLinear, kCubicSpline };

struct Track {
  uint32_t node = 0;  // index into SceneGraph::nodes
  TrsPart part = TrsPart::kTranslation;
  Interpolation interpolation = Interpolation::kLinear;
  std::vector<float> times;  // seconds, strictly increasing, at least one
  // One value per key (a vector in xyz, or a rotation as a unit quaternion x, y, z, w); cubic
  // spline: three per key, in-tangent, value, out-tangent (glTF's layout).
  std::vector<Vec4> values;
};

// The track's value at `seconds`.
Vec4 sample_track(const Track& track, float seconds);

// Spherical linear interpolation of unit quaternions (x, y, z, w), the shorter way round.
Vec4 slerp(Vec4 a, Vec4 b, float s);

// The node's transform with the track's value at `seconds` written into its part.
void apply_track(const Track& track, float seconds, Trs& trs);

}  // namespace rt
