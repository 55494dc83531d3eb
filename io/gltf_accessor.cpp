#include "io/gltf_accessor.h"

#include <algorithm>
#include <cstring>

#include <tiny_gltf.h>

namespace rt {
namespace {

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

int component_size(int type) {
  const int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(type));
  return size > 0 ? size : 0;
}

// Reads `count` elements of `components` components from a buffer view, bounds-checked.
bool read_view(const tinygltf::Model& model, int view_index, uint64_t byte_offset, uint64_t count, int components,
               int component_type, bool normalized, double* out, std::string& error) {
  if (view_index < 0 || view_index >= static_cast<int>(model.bufferViews.size())) {
    error = "bufferView " + std::to_string(view_index) + " does not exist";
    return false;
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(view_index)];
  if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) {
    error = "bufferView " + std::to_string(view_index) + " names buffer " + std::to_string(view.buffer) +
            ", which does not exist";
    return false;
  }
  const std::vector<unsigned char>& data = model.buffers[static_cast<size_t>(view.buffer)].data;
  const uint64_t csize = static_cast<uint64_t>(component_size(component_type));
  if (csize == 0) {
    error = "unknown component type " + std::to_string(component_type);
    return false;
  }
  const uint64_t element = csize * static_cast<uint64_t>(components);
  const uint64_t stride = view.byteStride ? view.byteStride : element;
  if (stride < element) {
    error = "bufferView " + std::to_string(view_index) + " has byteStride " + std::to_string(stride) +
            ", smaller than one element (" + std::to_string(element) + " bytes)";
    return false;
  }
  if (count == 0) return true;
  const uint64_t needed = byte_offset + stride * (count - 1) + element;
  if (needed > view.byteLength || uint64_t{view.byteOffset} + view.byteLength > data.size()) {
    error = "accessor reads " + std::to_string(needed) + " bytes from bufferView " + std::to_string(view_index) +
            ", which holds " +
            std::to_string(std::min<uint64_t>(view.byteLength,
                                              data.size() > view.byteOffset ? data.size() - view.byteOffset : 0)) +
            ": the file is truncated or inconsistent";
    return false;
  }
  const unsigned char* base = data.data() + view.byteOffset + byte_offset;
  for (uint64_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c)
      out[i * static_cast<uint64_t>(components) + static_cast<uint64_t>(c)] =
          read_component(base + i * stride + static_cast<uint64_t>(c) * csize, component_type, normalized);
  return true;
}

}  // namespace

bool read_accessor(const tinygltf::Model& model, int index, int components, std::vector<double>& out,
                   std::string& error) {
  if (index < 0 || index >= static_cast<int>(model.accessors.size())) {
    error = "accessor " + std::to_string(index) + " does not exist";
    return false;
  }
  const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
  const int found = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  if (found != components) {
    error = "accessor " + std::to_string(index) + " has " + std::to_string(found) +
            " components per element, expected " + std::to_string(components);
    return false;
  }
  const uint64_t count = a.count;
  if (count > (uint64_t{1} << 28)) {
    error = "accessor " + std::to_string(index) + " has " + std::to_string(count) +
            " elements, more than this renderer accepts (2^28)";
    return false;
  }
  out.assign(count * static_cast<uint64_t>(components), 0.0);  // no bufferView: zeros (then sparse values)
  if (a.bufferView >= 0 && !read_view(model, a.bufferView, a.byteOffset, count, components, a.componentType,
                                      a.normalized, out.data(), error)) {
    error = "accessor " + std::to_string(index) + ": " + error;
    return false;
  }
  if (!a.sparse.isSparse) return true;
  const auto n = static_cast<uint64_t>(std::max(0, a.sparse.count));
  std::vector<double> indices(n), values(n * static_cast<uint64_t>(components));
  if (!read_view(model, a.sparse.indices.bufferView, static_cast<uint64_t>(a.sparse.indices.byteOffset), n, 1,
                 a.sparse.indices.componentType, false, indices.data(), error) ||
      !read_view(model, a.sparse.values.bufferView, static_cast<uint64_t>(a.sparse.values.byteOffset), n, components,
                 a.componentType, a.normalized, values.data(), error)) {
    error = "sparse accessor " + std::to_string(index) + ": " + error;
    return false;
  }
  for (uint64_t k = 0; k < n; ++k) {
    if (!(indices[k] >= 0 && indices[k] < static_cast<double>(count))) {
      error = "sparse accessor " + std::to_string(index) + " substitutes element " + std::to_string(indices[k]) +
              " of " + std::to_string(count);
      return false;
    }
    const auto target = static_cast<uint64_t>(indices[k]);
    for (int c = 0; c < components; ++c)
      out[target * static_cast<uint64_t>(components) + static_cast<uint64_t>(c)] =
          values[k * static_cast<uint64_t>(components) + static_cast<uint64_t>(c)];
  }
  return true;
}

bool read_indices(const tinygltf::Model& model, int index, size_t vertex_count, std::vector<uint32_t>& out,
                  std::string& error) {
  std::vector<double> raw;
  if (!read_accessor(model, index, 1, raw, error)) return false;
  out.resize(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    if (!(raw[i] >= 0 && raw[i] < static_cast<double>(vertex_count))) {
      error = "index accessor " + std::to_string(index) + ": element " + std::to_string(i) + " is " +
              std::to_string(static_cast<long long>(raw[i])) + ", but there are only " + std::to_string(vertex_count) +
              " vertices";
      return false;
    }
    out[i] = static_cast<uint32_t>(raw[i]);
  }
  return true;
}

}  // namespace rt
