// Reading numbers out of glTF JSON that tinygltf leaves as generic values (extension objects,
// extras): a missing key, a wrong type or a number that is not finite reads as "not given".
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include <tiny_gltf.h>

namespace rt {

inline std::optional<float> gltf_number(const tinygltf::Value& object, const char* key) {
  if (!object.IsObject() || !object.Has(key) || !object.Get(key).IsNumber()) return std::nullopt;
  const double v = object.Get(key).GetNumberAsDouble();
  return std::isfinite(v) ? std::optional<float>(static_cast<float>(v)) : std::nullopt;
}

// An array of exactly `count` finite numbers.
inline std::optional<std::vector<float>> gltf_numbers(const tinygltf::Value& object, const char* key, int count) {
  if (!object.IsObject() || !object.Has(key)) return std::nullopt;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() != static_cast<size_t>(count)) return std::nullopt;
  std::vector<float> out;
  for (int i = 0; i < count; ++i) {
    if (!v.Get(i).IsNumber() || !std::isfinite(v.Get(i).GetNumberAsDouble())) return std::nullopt;
    out.push_back(static_cast<float>(v.Get(i).GetNumberAsDouble()));
  }
  return out;
}

}  // namespace rt
