// Reading glTF accessors safely. tinygltf parses the file but does not check that an accessor's
// bytes lie inside its buffer; these functions check every offset before reading, handle every
// component type glTF allows (normalised integers included) and apply sparse substitutions.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace rt {

// Accessor `index` as count x `components` values, converted to double (exact for every
// integer type). Fails, with a sentence in `error`, on any inconsistency.
bool read_accessor(const tinygltf::Model& model, int index, int components, std::vector<double>& out,
                   std::string& error);

// An index accessor (SCALAR, unsigned byte / short / int), each index checked < vertex_count.
bool read_indices(const tinygltf::Model& model, int index, size_t vertex_count, std::vector<uint32_t>& out,
                  std::string& error);

}  // namespace rt
