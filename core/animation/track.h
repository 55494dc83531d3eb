// Keyframed animation of one part of one node's transform, as glTF animation channels and the
// scene format's "animation" tracks describe it. Sampling between keys: step holds the earlier
// key; linear interpolates (rotations by spherical linear interpolation, the short way round);
// cubic spline is glTF's Hermite spline with in- and out-tangents per key (rotations
// renormalised). Before the first key the first value holds, after the last key the last.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/animation/trs.h"

namespace rt {

enum class TrsPart : uint8_t { kTranslation, kRotation, kScale };
enum class Interpolation : uint8_t { kStep, kLinear, kCubicSpline };

// A track's keys. Shared, never copied, by every track that plays them: glTF channels that use
// one sampler, and a file's tracks wherever the file is placed.
struct Keyframes {
  std::vector<float> times;  // seconds, strictly increasing, at least one
  // One value per key (a vector in xyz, or a rotation as a unit quaternion x, y, z, w); cubic
  // spline: three per key, in-tangent, value, out-tangent (glTF's layout).
  std::vector<Vec4> values;
};

struct Track {
  uint32_t node = 0;  // index into SceneGraph::nodes
  TrsPart part = TrsPart::kTranslation;
  Interpolation interpolation = Interpolation::kLinear;
  std::shared_ptr<const Keyframes> keys = std::make_shared<const Keyframes>();

  float end() const { return keys->times.empty() ? 0.0f : keys->times.back(); }  // the last key's time
};

// The track's value at `seconds`.
Vec4 sample_track(const Track& track, float seconds);

// Spherical linear interpolation of unit quaternions (x, y, z, w), the shorter way round.
Vec4 slerp(Vec4 a, Vec4 b, float s);

// The node's transform with the track's value at `seconds` written into its part.
void apply_track(const Track& track, float seconds, Trs& trs);

}  // namespace rt
