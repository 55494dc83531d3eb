#include "io/gltf/accessor.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

namespace rt {
namespace {

using std::to_string;

double read_component(const unsigned char* p, int type, bool normalized) {
  // glTF 2.0, "Animations" / "Meshes": normalised signed values clamp at -1.
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? v / 4294967295.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {  // TINYGLTF_COMPONENT_TYPE_DOUBLE: not core glTF, but harmless to accept
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
  }
}

uint64_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
    default: return 0;
  }
}

bool is_unsigned_integer(int type) {
  return type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

const char* component_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
    default: return "an unknown type";
  }
}

// Where `count` elements of one accessor (or one half of a sparse accessor) lie, once checked.
struct Elements {
  const unsigned char* first = nullptr;
  uint64_t stride = 0;
  int component_type = 0;
  uint64_t component_bytes = 0;
  int components = 0;
  bool normalized = false;

  double get(uint64_t i, int c) const {
    return read_component(first + i * stride + static_cast<uint64_t>(c) * component_bytes, component_type, normalized);
  }
};

// Where a problem is reported: the context that starts each message ("mesh 0 primitive 0
// POSITION: "), and the pointer of the value that names the accessor (used when it does not exist).
struct Site {
  Reporter& report;
  const std::string& context;
  const std::string& reference;
  bool fail(const std::string& pointer, const std::string& message) const {
    report.error(pointer, context + message);
    return false;
  }
};

std::string view_pointer(int index) { return "/bufferViews/" + to_string(index); }

// The view, if it lies inside its buffer (checked without overflow); else reported.
const tinygltf::BufferView* checked_view(const tinygltf::Model& model, int view_index, const std::string& reference,
                                         const Site& site) {
  if (view_index < 0 || static_cast<size_t>(view_index) >= model.bufferViews.size()) {
    site.fail(reference, "bufferView " + to_string(view_index) + " does not exist");
    return nullptr;
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(view_index)];
  const std::string at = view_pointer(view_index);
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
    site.fail(at + "/buffer", "bufferView " + to_string(view_index) + " names buffer " + to_string(view.buffer) +
                                  ", which does not exist");
    return nullptr;
  }
  const uint64_t size = model.buffers[static_cast<size_t>(view.buffer)].data.size();
  if (view.byteLength > size || view.byteOffset > size - view.byteLength) {
    site.fail(at + "/byteLength", "bufferView " + to_string(view_index) + " (bytes " + to_string(view.byteOffset) +
                                      " + " + to_string(view.byteLength) + ") does not lie inside buffer " +
                                      to_string(view.buffer) + ", which holds " + to_string(size) + " bytes");
    return nullptr;
  }
  if (view.byteStride != 0 && (view.byteStride < 4 || view.byteStride > 252 || view.byteStride % 4 != 0)) {
    site.fail(at + "/byteStride", "bufferView " + to_string(view_index) + " has byteStride " +
                                      to_string(view.byteStride) + "; glTF allows a multiple of 4 from 4 to 252");
    return nullptr;
  }
  return &view;
}

// Where a run of elements is described: the object with bufferView, byteOffset and
// componentType (an accessor, or a sparse accessor's indices or values), and its count.
struct ElementsAt {
  std::string owner;
  std::string count;
};

// Checks that `count` elements of `components` x component_type at byte_offset in the view lie
// inside it. All arithmetic is on values already known to be small, or in a form that cannot wrap.
bool locate(const tinygltf::Model& model, int view_index, uint64_t byte_offset, uint64_t count, int components,
            int component_type, bool normalized, Elements& out, const ElementsAt& at, const Site& site) {
  const tinygltf::BufferView* view = checked_view(model, view_index, at.owner + "/bufferView", site);
  if (!view) return false;
  const uint64_t csize = component_size(component_type);
  if (csize == 0) return site.fail(at.owner + "/componentType", "unknown component type " + to_string(component_type));
  const uint64_t element = csize * static_cast<uint64_t>(components);  // at most 8 x 16
  const uint64_t stride = view->byteStride ? view->byteStride : element;
  if (stride < element)
    return site.fail(view_pointer(view_index) + "/byteStride",
                     "bufferView " + to_string(view_index) + " has byteStride " + to_string(stride) +
                         ", smaller than one element (" + to_string(element) + " bytes)");
  const uint64_t length = view->byteLength;
  const bool fits = count == 0 || (element <= length && byte_offset <= length - element &&
                                   count - 1 <= (length - element - byte_offset) / stride);
  if (!fits)
    return site.fail(at.count, to_string(count) + " elements of " + to_string(element) + " bytes (stride " +
                                   to_string(stride) + ") from byte " + to_string(byte_offset) +
                                   " do not fit in bufferView " + to_string(view_index) + ", which holds " +
                                   to_string(length) + " bytes: the file is truncated or inconsistent");
  const auto& buffer = model.buffers[static_cast<size_t>(view->buffer)].data;
  out = Elements{buffer.data() + view->byteOffset + byte_offset, stride, component_type, csize, components, normalized};
  return true;
}

// Reads accessor `index` into `out` (count x components), applying `convert` to each value;
// convert returns an empty string, or why it rejects the value.
template <class T, class Convert>
bool read_accessor(const tinygltf::Model& model, int index, int components, uint64_t max_elements, std::vector<T>& out,
                   const Site& site, const Convert& convert) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
    return site.fail(site.reference, "accessor " + to_string(index) + " does not exist");
  const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
  const std::string name = "accessor " + to_string(index);
  const std::string at = "/accessors/" + to_string(index);
  const int found = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  if (found != components)
    return site.fail(at + "/type",
                     name + " has " + to_string(found) + " components per element, expected " + to_string(components));
  const uint64_t count = a.count;
  if (count == 0) return site.fail(at + "/count", name + " has count 0; glTF requires at least 1");
  if (count > max_elements)
    return site.fail(at + "/count", name + " has " + to_string(count) + " elements, more than the " +
                                        to_string(max_elements) + " this renderer accepts");
  const std::string inner_context = site.context + name + ": ";
  const Site inner{site.report, inner_context, site.reference};
  Elements dense;
  if (a.bufferView >= 0 && !locate(model, a.bufferView, a.byteOffset, count, components, a.componentType, a.normalized,
                                   dense, ElementsAt{at, at + "/count"}, inner))
    return false;
  if (a.bufferView < 0 && component_size(a.componentType) == 0)
    return inner.fail(at + "/componentType", "unknown component type " + to_string(a.componentType));
  Elements sparse_indices, sparse_values;
  uint64_t substitutions = 0;
  const std::string sname = "sparse " + name;
  const std::string sparse_at = at + "/sparse";
  if (a.sparse.isSparse) {
    if (a.sparse.count < 1 || static_cast<uint64_t>(a.sparse.count) > count)
      return site.fail(sparse_at + "/count", sname + " substitutes " + to_string(a.sparse.count) +
                                                 " elements; glTF requires 1 to count (" + to_string(count) + ")");
    if (!is_unsigned_integer(a.sparse.indices.componentType))
      return site.fail(sparse_at + "/indices/componentType",
                       sname + " has indices of type " + component_name(a.sparse.indices.componentType) +
                           "; glTF allows UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
      return site.fail(sparse_at, sname + " has a negative byteOffset");
    substitutions = static_cast<uint64_t>(a.sparse.count);
    const std::string sparse_context = site.context + sname + ": ";
    const Site sparse{site.report, sparse_context, site.reference};
    if (!locate(model, a.sparse.indices.bufferView, static_cast<uint64_t>(a.sparse.indices.byteOffset), substitutions,
                1, a.sparse.indices.componentType, false, sparse_indices,
                ElementsAt{sparse_at + "/indices", sparse_at + "/count"}, sparse) ||
        !locate(model, a.sparse.values.bufferView, static_cast<uint64_t>(a.sparse.values.byteOffset), substitutions,
                components, a.componentType, a.normalized, sparse_values,
                ElementsAt{sparse_at + "/values", sparse_at + "/count"}, sparse))
      return false;
  }
  // Everything is known to be inside the data: now allocate.
  out.assign(count * static_cast<uint64_t>(components), T{});  // no bufferView: zeros (then sparse values)
  for (uint64_t i = 0; a.bufferView >= 0 && i < count; ++i)
    for (int c = 0; c < components; ++c)
      if (const std::string why =
              convert(dense.get(i, c), i, out[i * static_cast<uint64_t>(components) + static_cast<uint64_t>(c)]);
          !why.empty())
        return inner.fail(at, why);
  double previous = -1.0;
  for (uint64_t k = 0; k < substitutions; ++k) {
    const double target = sparse_indices.get(k, 0);
    if (!(target < static_cast<double>(count)) || !(target > previous))
      return site.fail(sparse_at + "/indices",
                       "sparse " + name + " substitutes element " + to_string(static_cast<uint64_t>(target)) +
                           (target < static_cast<double>(count) ? " out of order (glTF requires increasing indices)"
                                                                : " of " + to_string(count)));
    previous = target;
    const auto i = static_cast<uint64_t>(target);
    for (int c = 0; c < components; ++c)
      if (const std::string why = convert(sparse_values.get(k, c), i,
                                          out[i * static_cast<uint64_t>(components) + static_cast<uint64_t>(c)]);
          !why.empty())
        return site.fail(sparse_at + "/values", "sparse " + name + ": " + why);
  }
  return true;
}

}  // namespace

uint64_t accessor_count(const tinygltf::Model& model, int index) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) return 0;
  return model.accessors[static_cast<size_t>(index)].count;
}

bool check_buffer_views(const tinygltf::Model& model, Reporter& report) {
  const std::string context;
  const Site site{report, context, context};
  for (size_t i = 0; i < model.bufferViews.size(); ++i)
    if (!checked_view(model, static_cast<int>(i), view_pointer(static_cast<int>(i)), site)) return false;
  return true;
}

bool read_float_accessor(const tinygltf::Model& model, int index, int components, uint64_t max_elements,
                         std::vector<float>& out, const AccessorUse& use) {
  return read_accessor(model, index, components, max_elements, out, Site{use.report, use.context, use.reference},
                       [](double v, uint64_t, float& to) {
                         to = static_cast<float>(v);  // beyond the float range: infinities, caught by the callers
                         return std::string();
                       });
}

bool read_index_accessor(const tinygltf::Model& model, int index, uint64_t max_elements, uint64_t vertex_count,
                         std::vector<uint32_t>& out, const AccessorUse& use) {
  const Site site{use.report, use.context, use.reference};
  if (index >= 0 && static_cast<size_t>(index) < model.accessors.size()) {
    const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
    if (!is_unsigned_integer(a.componentType) || a.normalized)
      return site.fail("/accessors/" + to_string(index) + "/componentType",
                       "index accessor " + to_string(index) + " has component type " + component_name(a.componentType) +
                           (a.normalized ? " (normalized)" : "") +
                           "; glTF allows only UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
  return read_accessor(model, index, 1, max_elements, out, site, [&](double v, uint64_t i, uint32_t& to) {
    if (!(v < static_cast<double>(vertex_count)))
      return "element " + to_string(i) + " is index " + to_string(static_cast<uint64_t>(v)) + ", but there are only " +
             to_string(vertex_count) + " vertices";
    to = static_cast<uint32_t>(v);
    return std::string();
  });
}

}  // namespace rt
