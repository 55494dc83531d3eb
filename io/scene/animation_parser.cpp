#include "io/scene/animation_parser.h"

#include <cmath>

#include "io/json/locate.h"

namespace rt {
namespace {

const std::vector<std::string> kParts = {"translate", "rotate", "scale"};
const std::vector<std::string> kInterpolations = {"linear", "step"};
constexpr float kMaxWrittenStep = 90.0f;  // degrees between the keys slerp is given

// A rotation key as written: what it is in degrees (to subdivide wide steps) and as a quaternion.
struct RotationKey {
  enum Form { kEuler, kAxisAngle, kQuaternion } form = kEuler;
  Vec3 euler{0.0f};  // kEuler: degrees
  Vec3 axis{0.0f, 1.0f, 0.0f};
  float degrees = 0.0f;  // kAxisAngle
  Quat quaternion{1.0f, 0.0f, 0.0f, 0.0f};
};

Vec4 as_vec4(const Quat& q) { return Vec4(q.x, q.y, q.z, q.w); }

std::optional<RotationKey> read_rotation(const JsonReader& r, const Json& v, const std::string& ptr) {
  RotationKey key;
  if (v.is_array()) {
    const auto e = read_vec3(r, v, ptr);
    if (!e) return std::nullopt;
    key.euler = *e;
    key.quaternion = euler_degrees_to_quat(*e);
    return key;
  }
  if (!v.is_object()) {
    r.expected(ptr,
               "a rotation: Euler degrees [x, y, z], {\"axis\": [x, y, z], \"degrees\": d} or "
               "{\"quaternion\": [x, y, z, w]}",
               v);
    return std::nullopt;
  }
  ObjectReader o(r, v, ptr);
  std::optional<RotationKey> out;
  if (const Json* q = o.get("quaternion")) {
    const std::string qp = o.child("quaternion");
    bool ok = q->is_array() && q->size() == 4;
    Vec4 c(0.0f);
    for (size_t i = 0; ok && i < 4; ++i) {
      const auto x = read_number(r, (*q)[i], pointer_child(qp, i), kAnyNumber);
      ok = x.has_value();
      if (ok) c[static_cast<int>(i)] = static_cast<float>(*x);
    }
    if (!q->is_array() || q->size() != 4) r.expected(qp, "a quaternion [x, y, z, w] of 4 numbers", *q);
    else if (ok && !(glm::length(c) > 0.0f)) r.expected(qp, "a quaternion of non-zero length", *q);
    else if (ok) {
      c = glm::normalize(c);
      key.form = RotationKey::kQuaternion;
      key.quaternion = Quat(c.w, c.x, c.y, c.z);
      out = key;
    }
    for (const char* other : {"axis", "degrees"})
      if (o.get(other))
        r.error(o.child(other), "expected either \"quaternion\" or axis and degrees, found both", Anchor::kKey);
  } else {
    const auto axis = o.vec3("axis", true);
    const auto degrees = o.number("degrees", kAnyNumber, true);
    if (axis && !(glm::length(*axis) > 0.0f)) r.expected(o.child("axis"), "an axis of non-zero length", v["axis"]);
    else if (axis && degrees) {
      key.form = RotationKey::kAxisAngle;
      key.axis = glm::normalize(*axis);
      key.degrees = static_cast<float>(*degrees);
      key.quaternion = axis_angle_to_quat(key.axis, key.degrees);
      out = key;
    }
  }
  o.finish();
  return out;
}

// Written degrees between two keys, when both are written in degrees about comparable axes.
float written_step(const RotationKey& a, const RotationKey& b) {
  if (a.form == RotationKey::kEuler && b.form == RotationKey::kEuler) return max_abs_component(b.euler - a.euler);
  if (a.form == RotationKey::kAxisAngle && b.form == RotationKey::kAxisAngle && glm::dot(a.axis, b.axis) > 0.9999f)
    return std::fabs(b.degrees - a.degrees);
  return 0.0f;
}

Quat between(const RotationKey& a, const RotationKey& b, float s) {
  if (a.form == RotationKey::kEuler) return euler_degrees_to_quat(glm::mix(a.euler, b.euler, s));
  return axis_angle_to_quat(a.axis, a.degrees + s * (b.degrees - a.degrees));
}

// Steps of at most 90 written degrees per linear rotation step (1 where it is narrower); the
// track then has 1 + their sum keys. In double: wide steps can need more than any integer holds.
std::vector<double> rotation_steps(const std::vector<RotationKey>& rotations) {
  std::vector<double> steps(rotations.size(), 1.0);
  for (size_t k = 1; k < rotations.size(); ++k)
    steps[k] = std::max(1.0, std::ceil(static_cast<double>(written_step(rotations[k - 1], rotations[k])) /
                                       static_cast<double>(kMaxWrittenStep)));
  return steps;
}

// The track with its wide rotation steps split as `steps` says.
void split_wide_rotations(const std::vector<RotationKey>& rotations, const std::vector<double>& steps, double total,
                          Track& track) {
  const std::vector<float>& times = track.keys->times;
  Keyframes dense;
  dense.times.reserve(static_cast<size_t>(total));
  dense.values.reserve(static_cast<size_t>(total));
  dense.times.push_back(times[0]);
  dense.values.push_back(track.keys->values[0]);
  for (size_t k = 1; k < rotations.size(); ++k) {
    const auto n = static_cast<int64_t>(steps[k]);
    for (int64_t s = 1; s < n; ++s) {
      const float f = static_cast<float>(static_cast<double>(s) / steps[k]);
      dense.times.push_back(glm::mix(times[k - 1], times[k], f));
      dense.values.push_back(as_vec4(between(rotations[k - 1], rotations[k], f)));
    }
    dense.times.push_back(times[k]);
    dense.values.push_back(track.keys->values[k]);
  }
  track.keys = std::make_shared<const Keyframes>(std::move(dense));
}

std::optional<TrackDescription> parse_track(const JsonReader& r, const Json& v, const std::string& ptr, float fps,
                                            uint64_t keys_left, uint64_t keys_limit) {
  ObjectReader o(r, v, ptr);
  TrackDescription t;
  t.pointer = ptr;
  const auto node = o.string("node", true);
  std::optional<size_t> part, interpolation = 0;
  if (const Json* p = o.get("property", true, "one of \"translate\", \"rotate\", \"scale\""))
    part = read_choice(r, *p, o.child("property"), kParts);
  if (const Json* i = o.get("interpolation"))
    interpolation = read_choice(r, *i, o.child("interpolation"), kInterpolations);
  const Json* keys = o.get("keys", true, "an array of keys {\"frame\": f, \"value\": v}");
  o.finish();
  if (!node || !part || !interpolation || !keys) return std::nullopt;
  const std::string keys_ptr = o.child("keys");
  if (!keys->is_array() || keys->empty()) {
    r.expected(keys_ptr, "a non-empty array of keys {\"frame\": f, \"value\": v}", *keys);
    return std::nullopt;
  }
  t.node = *node;
  t.track.part = static_cast<TrsPart>(*part);
  t.track.interpolation = *interpolation == 1 ? Interpolation::kStep : Interpolation::kLinear;
  std::vector<RotationKey> rotations;
  Keyframes keyframes;
  bool ok = true;
  for (size_t k = 0; k < keys->size(); ++k) {
    const std::string kp = pointer_child(keys_ptr, k);
    ObjectReader key(r, (*keys)[k], kp);
    const auto frame = key.number("frame", kAnyNumber, true);
    const Json* value = key.get("value", true, "the value at this frame");
    key.finish();
    if (!frame || !value) {
      ok = false;
      continue;
    }
    const float seconds = static_cast<float>(*frame / fps);
    if (!keyframes.times.empty() && !(seconds > keyframes.times.back())) {
      r.error(key.child("frame"), "expected frames in increasing order, found " + describe((*keys)[k]["frame"]) +
                                      " after a key at frame " + std::to_string(keyframes.times.back() * fps));
      ok = false;
      continue;
    }
    const std::string vp = key.child("value");
    std::optional<Vec4> out;
    if (t.track.part == TrsPart::kRotation) {
      if (const auto rot = read_rotation(r, *value, vp)) {
        rotations.push_back(*rot);
        out = as_vec4(rot->quaternion);
      }
    } else if (t.track.part == TrsPart::kScale && value->is_number()) {
      if (const auto x = read_number(r, *value, vp, kAnyNumber)) out = Vec4(Vec3(static_cast<float>(*x)), 0.0f);
    } else if (const auto x = read_vec3(r, *value, vp)) {
      out = Vec4(*x, 0.0f);
    }
    if (!out) {
      ok = false;
      continue;
    }
    keyframes.times.push_back(seconds);
    keyframes.values.push_back(*out);
  }
  if (!ok) return std::nullopt;
  t.track.keys = std::make_shared<const Keyframes>(std::move(keyframes));
  // Degrees mean what they say: a wide linear step becomes several steps of at most 90 degrees.
  // The keys that makes are counted before any is made.
  const bool split = t.track.part == TrsPart::kRotation && t.track.interpolation == Interpolation::kLinear;
  const std::vector<double> steps = split ? rotation_steps(rotations) : std::vector<double>{};
  double total = 1.0;
  for (size_t k = 1; k < steps.size(); ++k) total += steps[k];
  if (!split) total = static_cast<double>(t.track.keys->times.size());
  if (total > static_cast<double>(keys_left)) {
    r.error(
        ptr + "/keys",
        "expected at most " + std::to_string(keys_limit) + " animation keys in a scene" +
            (split ? ", counting the steps of at most 90 degrees that wide rotations are split into," : "") +
            " found " + (total > 1e15 ? std::string("more than 10^15") : std::to_string(static_cast<uint64_t>(total))) +
            " in this track" +
            (keys_left < keys_limit ? " after " + std::to_string(keys_limit - keys_left) + " in the tracks before it"
                                    : "") +
            " (a limit that keeps memory bounded; see docs/errors-and-limits.md, \"Limits\")");
    return std::nullopt;
  }
  if (split) split_wide_rotations(rotations, steps, total, t.track);
  return t;
}

}  // namespace

std::optional<AnimationDescription> parse_animation(const JsonReader& r, const Json& value, const std::string& ptr,
                                                    uint64_t max_keys) {
  ObjectReader o(r, value, ptr);
  if (!o.valid()) {
    r.expected(ptr, "an object with fps, frames and tracks", value);
    return std::nullopt;
  }
  AnimationDescription a;
  a.pointer = ptr;
  if (const auto fps = o.number("fps", NumberRule{0.0, 1000.0, true, false, false})) a.fps = static_cast<float>(*fps);
  if (const Json* frames = o.get("frames")) {
    const std::string fp = o.child("frames");
    const NumberRule frame_rule{-1e6, 1e6, false, false, true};
    if (!frames->is_array() || frames->size() != 2) {
      r.expected(fp, "[first, last]: two whole frame numbers, first <= last", *frames);
    } else {
      const auto first = read_number(r, (*frames)[0], pointer_child(fp, 0), frame_rule);
      const auto last = read_number(r, (*frames)[1], pointer_child(fp, 1), frame_rule);
      if (first && last && *last < *first) r.expected(fp, "[first, last] with first <= last", *frames);
      else if (first && last) {
        a.first_frame = static_cast<int>(*first);
        a.last_frame = static_cast<int>(*last);
      }
    }
  }
  if (const Json* tracks = o.get("tracks")) {
    const std::string tp = o.child("tracks");
    if (!tracks->is_array()) {
      r.expected(tp, "an array of tracks", *tracks);
    } else {
      uint64_t keys = 0;
      for (size_t i = 0; i < tracks->size(); ++i) {
        auto t = parse_track(r, (*tracks)[i], pointer_child(tp, i), a.fps, max_keys - keys, max_keys);
        if (!t) continue;
        keys += t->track.keys->times.size();
        a.tracks.push_back(std::move(*t));
      }
    }
  }
  o.finish();
  return a;
}

}  // namespace rt
