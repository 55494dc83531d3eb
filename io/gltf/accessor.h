// Reading glTF accessors safely. tinygltf parses the file but checks neither bufferViews against
// their buffers nor accessors against their views. These functions do, in forms that cannot
// overflow (no `offset + length` on untrusted 64-bit values), and they check an accessor's count
// against its data and the caller's limit before anything is allocated. They handle every
// component type glTF allows (normalised integers as the specification converts them) and
// sparse substitution. Every failure is reported with the pointer of the value at fault.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/base/reporter.h"

namespace tinygltf {
class Model;
}

namespace rt {

// Every bufferView lies inside its buffer and has a stride glTF allows. Once per file, after
// loading; the readers below check again what they read, so they are safe on their own too.
bool check_buffer_views(const tinygltf::Model& model, Reporter& report);

// The count accessor `index` claims (0 if there is no such accessor), for budgets checked before
// anything is read; the readers below check it against the data.
uint64_t accessor_count(const tinygltf::Model& model, int index);

// Who reads an accessor, for the reports: `context` starts each message ("mesh 0 primitive 0
// POSITION: "), `reference` is the pointer of the value naming the accessor (reported when it does
// not exist). Problems inside the accessor are reported at its own pointer (/accessors/3/count).
struct AccessorUse {
  Reporter& report;
  std::string context;
  std::string reference;
};

// Accessor `index` as count x `components` floats, count at most max_elements.
bool read_float_accessor(const tinygltf::Model& model, int index, int components, uint64_t max_elements,
                         std::vector<float>& out, const AccessorUse& use);

// An index accessor: SCALAR, unsigned byte, short or int (glTF allows no other), at most
// max_elements, each index < vertex_count.
bool read_index_accessor(const tinygltf::Model& model, int index, uint64_t max_elements, uint64_t vertex_count,
                         std::vector<uint32_t>& out, const AccessorUse& use);

}  // namespace rt
