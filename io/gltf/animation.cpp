#include "io/gltf/animation.h"

#include <cmath>
#include <map>
#include <memory>

#include <tiny_gltf.h>

#include "io/gltf/accessor.h"

namespace rt {
namespace {

using std::to_string;

bool fail(Reporter& report, const std::string& pointer, const std::string& message) {
  report.error(pointer, message);
  return false;
}

// A sampler's keys as one kind of channel reads them (3 or 4 components, rotations normalised).
std::shared_ptr<const Keyframes> read_keys(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler,
                                           TrsPart part, Interpolation interpolation, const LoadLimits& limits,
                                           const std::string& where, const std::string& at, Reporter& report) {
  Keyframes keys;
  std::vector<float> raw;
  const std::string input_at = "/accessors/" + to_string(sampler.input);
  if (!read_float_accessor(model, sampler.input, 1, limits.animation_keys, raw,
                           AccessorUse{report, where + " input: ", at + "/input"}))
    return nullptr;
  if (raw.empty()) {
    fail(report, input_at, where + " input: expected at least one key time, found none");
    return nullptr;
  }
  for (size_t k = 0; k < raw.size(); ++k) {
    if (!std::isfinite(raw[k])) {
      fail(report, input_at, where + " input: key " + to_string(k) + " is not a finite time");
      return nullptr;
    }
    if (k > 0 && !(raw[k] > raw[k - 1])) {
      fail(report, input_at,
           where + " input: expected strictly increasing key times, found " + to_string(raw[k]) + " after " +
               to_string(raw[k - 1]));
      return nullptr;
    }
  }
  keys.times = std::move(raw);
  const int components = part == TrsPart::kRotation ? 4 : 3;
  const size_t per_key = interpolation == Interpolation::kCubicSpline ? 3 : 1;
  const std::string output_at = "/accessors/" + to_string(sampler.output);
  if (!read_float_accessor(model, sampler.output, components, per_key * limits.animation_keys, raw,
                           AccessorUse{report, where + " output: ", at + "/output"}))
    return nullptr;
  const size_t values = raw.size() / static_cast<size_t>(components);
  if (values != per_key * keys.times.size()) {
    fail(report, output_at + "/count",
         where + " output: expected " + to_string(per_key * keys.times.size()) + " values (" +
             (per_key == 3 ? "in-tangent, value and out-tangent for each of " : "one for each of ") +
             to_string(keys.times.size()) + " keys), found " + to_string(values));
    return nullptr;
  }
  keys.values.resize(values);
  for (size_t i = 0; i < values; ++i) {
    Vec4 v(0.0f);
    for (int k = 0; k < components; ++k) v[k] = raw[i * static_cast<size_t>(components) + static_cast<size_t>(k)];
    if (!is_finite(v)) {
      fail(report, output_at, where + " output: value " + to_string(i) + " is not finite");
      return nullptr;
    }
    keys.values[i] = v;
  }
  if (part == TrsPart::kRotation) {
    // Key values must be unit quaternions (tangents need not be): normalise them.
    for (size_t k = 0; k < keys.times.size(); ++k) {
      Vec4& q = keys.values[per_key == 3 ? 3 * k + 1 : k];
      const float len = glm::length(q);
      q = len > 0.0f ? q / len : Vec4(0.0f, 0.0f, 0.0f, 1.0f);
    }
  }
  return std::make_shared<const Keyframes>(std::move(keys));
}

// The animation `which` names: by name first, then as an index ("2"); -1 if none.
int find_animation(const tinygltf::Model& model, const std::string& which) {
  for (size_t i = 0; i < model.animations.size(); ++i)
    if (model.animations[i].name == which) return static_cast<int>(i);
  if (!which.empty() && which.size() <= 9 && which.find_first_not_of("0123456789") == std::string::npos) {
    const size_t index = std::stoul(which);
    if (index < model.animations.size()) return static_cast<int>(index);
  }
  return -1;
}

// One animation's channels as tracks.
bool import_animation(const tinygltf::Model& model, size_t index, const std::vector<int32_t>& node_map,
                      const LoadLimits& limits, LimitUsage& usage, ImportedModel& out, Reporter& report) {
  const tinygltf::Animation& animation = model.animations[index];
  const std::string prefix = "/animations/" + to_string(index);
  // Per sampler and channel kind (a sampler may serve translation and scale alike): its keys.
  std::map<std::pair<int, TrsPart>, std::shared_ptr<const Keyframes>> shared;
  for (size_t c = 0; c < animation.channels.size(); ++c) {
    const tinygltf::AnimationChannel& channel = animation.channels[c];
    const std::string where = "animation " + to_string(index) + " channel " + to_string(c);
    const std::string at = prefix + "/channels/" + to_string(c);
    Track track;
    if (channel.target_path == "translation") track.part = TrsPart::kTranslation;
    else if (channel.target_path == "rotation") track.part = TrsPart::kRotation;
    else if (channel.target_path == "scale") track.part = TrsPart::kScale;
    else {
      report.warning(at + "/target/path", where + ": \"" + channel.target_path + "\" channels are not played; skipped");
      continue;
    }
    if (channel.target_node < 0 || static_cast<size_t>(channel.target_node) >= node_map.size())
      return fail(report, at + "/target/node",
                  where + ": target node " + to_string(channel.target_node) + " does not exist");
    const int32_t node = node_map[static_cast<size_t>(channel.target_node)];
    if (node < 0) {
      report.warning(at + "/target/node",
                     where + ": node " + to_string(channel.target_node) + " is not in the default scene; skipped");
      continue;
    }
    if (out.nodes[static_cast<size_t>(node)].matrix)
      return fail(report, "/nodes/" + to_string(channel.target_node) + "/matrix",
                  where + ": node " + to_string(channel.target_node) +
                      " has a \"matrix\"; glTF allows animating only nodes with translation, rotation and scale");
    track.node = static_cast<uint32_t>(node);
    if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= animation.samplers.size())
      return fail(report, at + "/sampler", where + ": sampler " + to_string(channel.sampler) + " does not exist");
    const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
    const std::string sampler_at = prefix + "/samplers/" + to_string(channel.sampler);
    if (sampler.interpolation == "STEP") track.interpolation = Interpolation::kStep;
    else if (sampler.interpolation == "CUBICSPLINE") track.interpolation = Interpolation::kCubicSpline;
    else if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty())
      track.interpolation = Interpolation::kLinear;
    else
      return fail(
          report, sampler_at + "/interpolation",
          where + ": expected interpolation LINEAR, STEP or CUBICSPLINE, found \"" + sampler.interpolation + "\"");

    std::shared_ptr<const Keyframes>& keys = shared[{channel.sampler, track.part}];
    if (!keys) {
      const uint64_t count = accessor_count(model, sampler.input);
      if (count > limits.animation_keys || usage.animation_keys > limits.animation_keys - count) {
        report.over_limit(
            "/accessors/" + to_string(sampler.input) + "/count",
            where + ": expected at most " + to_string(limits.animation_keys) + " animation keys in a scene, found " +
                to_string(count) + " in this sampler" +
                (usage.animation_keys ? " after " + to_string(usage.animation_keys) + " before it" : std::string()));
        return false;
      }
      keys = read_keys(model, sampler, track.part, track.interpolation, limits, where, sampler_at, report);
      if (!keys) return false;
      usage.animation_keys += count;
    }
    track.keys = keys;
    out.animation_end = std::max(out.animation_end, track.end());
    out.tracks.push_back(std::move(track));
  }
  return true;
}

}  // namespace

bool import_animations(const tinygltf::Model& model, const std::vector<int32_t>& node_map,
                       const std::optional<std::string>& which, const LoadLimits& limits, LimitUsage& usage,
                       ImportedModel& out, Reporter& report, ImportError& error) {
  if (which) {
    const int index = find_animation(model, *which);
    if (index < 0) {
      std::string names;
      for (size_t i = 0; i < model.animations.size() && i < 20; ++i)
        names += (i ? ", \"" : "\"") + model.animations[i].name + "\" (" + to_string(i) + ")";
      if (model.animations.size() > 20) names += ", ...";
      error.unknown_animation = true;
      error.message = "its animations are " + (names.empty() ? std::string("none") : names);
      return false;
    }
    return import_animation(model, static_cast<size_t>(index), node_map, limits, usage, out, report);
  }
  // All of them together, as the Khronos sample viewer plays a file.
  for (size_t i = 0; i < model.animations.size(); ++i)
    if (!import_animation(model, i, node_map, limits, usage, out, report)) return false;
  return true;
}

}  // namespace rt
