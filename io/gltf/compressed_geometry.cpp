#include "io/gltf/compressed_geometry.h"

#include <cstring>
#include <memory>

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <meshoptimizer.h>

#include "io/base/base64.h"
#include "io/json/locate.h"

namespace rt {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";
constexpr const char* kMeshopt = "EXT_meshopt_compression";
constexpr const char* kMeshoptKhr = "KHR_meshopt_compression";  // the same scheme under its later name

const Json* object_at(const Json& parent, const char* key) {
  const auto it = parent.find(key);
  return it != parent.end() && it->is_object() ? &*it : nullptr;
}

// A non-negative integer member below `bound`, or -1.
int64_t index_at(const Json& parent, const char* key, size_t bound) {
  const auto it = parent.find(key);
  if (it == parent.end() || !it->is_number_integer()) return -1;
  const int64_t v = it->get<int64_t>();
  return v >= 0 && static_cast<uint64_t>(v) < bound ? v : -1;
}

uint64_t size_at(const Json& parent, const char* key, uint64_t otherwise = 0) {
  const auto it = parent.find(key);
  if (it == parent.end() || !it->is_number_unsigned()) return otherwise;
  return it->get<uint64_t>();
}

int components_of(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  return 0;
}

void drop_extension_name(Json& document, const char* name) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
    auto it = document.find(list);
    if (it == document.end() || !it->is_array()) continue;
    Json kept = Json::array();
    for (const Json& e : *it)
      if (!(e.is_string() && e.get<std::string>() == name)) kept.push_back(e);
    *it = kept;
  }
}

// The bytes of a buffer view (bounds checked), or null.
const unsigned char* view_bytes(const std::vector<std::vector<unsigned char>>& buffers, const Json& view,
                                uint64_t& length) {
  const int64_t buffer = index_at(view, "buffer", buffers.size());
  if (buffer < 0) return nullptr;
  const uint64_t offset = size_at(view, "byteOffset"), size = size_at(view, "byteLength");
  const auto& data = buffers[static_cast<size_t>(buffer)];
  if (offset > data.size() || size > data.size() - offset) return nullptr;
  length = size;
  return data.data() + offset;
}

class Decoder {
 public:
  Decoder(Json& document, const std::vector<std::vector<unsigned char>>& buffers, uint64_t budget, Reporter& report)
      : doc_(document), buffers_(buffers), budget_(budget), report_(report) {}

  bool run() {
    if (!meshopt_views()) return false;
    if (!draco_primitives()) return false;
    if (!decoded_.empty()) {
      doc_["buffers"].push_back(embedded_buffer(decoded_));
    }
    drop_extension_name(doc_, kDraco);
    drop_extension_name(doc_, kMeshopt);
    drop_extension_name(doc_, kMeshoptKhr);
    return true;
  }

 private:
  // Appends bytes to the new buffer (4-byte aligned); their offset in it.
  bool append(const void* data, uint64_t size, uint64_t& offset, const std::string& at) {
    while (decoded_.size() % 4) decoded_.push_back(0);
    if (size > budget_ || decoded_.size() > budget_ - size) {
      report_.error(at, "its decoded data would exceed the model's budget of bytes (--max-gltf-bytes)");
      return false;
    }
    offset = decoded_.size();
    const auto* bytes = static_cast<const unsigned char*>(data);
    decoded_.insert(decoded_.end(), bytes, bytes + size);
    return true;
  }

  size_t new_buffer_index() const { return doc_["buffers"].size(); }

  Json& views() { return doc_["bufferViews"]; }

  bool meshopt_views() {
    auto it = doc_.find("bufferViews");
    if (it == doc_.end() || !it->is_array()) return true;
    for (size_t v = 0; v < it->size(); ++v) {
      Json& view = (*it)[v];
      if (!view.is_object()) continue;
      const Json* extensions = object_at(view, "extensions");
      if (!extensions) continue;
      const char* name = object_at(*extensions, kMeshopt)      ? kMeshopt
                         : object_at(*extensions, kMeshoptKhr) ? kMeshoptKhr
                                                               : nullptr;
      if (!name) continue;
      const Json ext = (*extensions)[name];
      const std::string at = "/bufferViews/" + std::to_string(v) + "/extensions/" + name;
      uint64_t length = 0;
      const unsigned char* src = view_bytes(buffers_, ext, length);
      const uint64_t count = size_at(ext, "count"), stride = size_at(ext, "byteStride");
      const std::string mode = ext.value("mode", std::string());
      const std::string filter = ext.value("filter", std::string("NONE"));
      if (!src) {
        report_.error(at, "expected a buffer, byteOffset and byteLength inside the buffer's data");
        return false;
      }
      const bool attributes = mode == "ATTRIBUTES";
      if (!(attributes || mode == "TRIANGLES" || mode == "INDICES")) {
        report_.error(at + "/mode", "expected one of \"ATTRIBUTES\", \"TRIANGLES\", \"INDICES\"");
        return false;
      }
      if (attributes ? (stride == 0 || stride > 256 || stride % 4 != 0) : (stride != 2 && stride != 4)) {
        report_.error(at + "/byteStride", attributes ? "expected a multiple of 4 up to 256" : "expected 2 or 4");
        return false;
      }
      if (count == 0 || count > budget_ / stride || (!attributes && count % (mode == "TRIANGLES" ? 3 : 1) != 0)) {
        report_.error(at + "/count", "expected a count whose decoded bytes fit the model's budget");
        return false;
      }
      std::vector<unsigned char> out(static_cast<size_t>(count * stride));
      int result = -1;
      if (attributes) result = meshopt_decodeVertexBuffer(out.data(), count, stride, src, length);
      else if (mode == "TRIANGLES") result = meshopt_decodeIndexBuffer(out.data(), count, stride, src, length);
      else result = meshopt_decodeIndexSequence(out.data(), count, stride, src, length);
      if (result != 0) {
        report_.error(at,
                      "its compressed data could not be decoded (meshoptimizer error " + std::to_string(result) + ")");
        return false;
      }
      if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8)) meshopt_decodeFilterOct(out.data(), count, stride);
      else if (filter == "QUATERNION" && stride == 8) meshopt_decodeFilterQuat(out.data(), count, stride);
      else if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), count, stride);
      else if (filter != "NONE") {
        report_.error(at + "/filter", "expected NONE, OCTAHEDRAL (byteStride 4 or 8), QUATERNION (8) or EXPONENTIAL");
        return false;
      }
      uint64_t offset = 0;
      if (!append(out.data(), out.size(), offset, at)) return false;
      view["buffer"] = new_buffer_index();
      view["byteOffset"] = offset;
      view["byteLength"] = out.size();
      if (attributes) view["byteStride"] = stride;
      else view.erase("byteStride");
      view["extensions"].erase(name);
      if (view["extensions"].empty()) view.erase("extensions");
    }
    // Fallback buffers have no data of their own: give them none.
    if (auto b = doc_.find("buffers"); b != doc_.end() && b->is_array())
      for (Json& buffer : *b) {
        const Json* extensions = buffer.is_object() ? object_at(buffer, "extensions") : nullptr;
        if (!extensions || !(object_at(*extensions, kMeshopt) || object_at(*extensions, kMeshoptKhr))) continue;
        if (buffer.contains("uri")) continue;
        buffer = embedded_buffer({0, 0, 0, 0});
      }
    return true;
  }

  bool draco_primitives() {
    auto meshes = doc_.find("meshes");
    auto accessors = doc_.find("accessors");
    if (meshes == doc_.end() || !meshes->is_array()) return true;
    for (size_t m = 0; m < meshes->size(); ++m) {
      Json& mesh = (*meshes)[m];
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (size_t p = 0; p < mesh["primitives"].size(); ++p) {
        Json& primitive = mesh["primitives"][p];
        const Json* extensions = primitive.is_object() ? object_at(primitive, "extensions") : nullptr;
        const Json* draco = extensions ? object_at(*extensions, kDraco) : nullptr;
        if (!draco) continue;
        const std::string at =
            "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p) + "/extensions/" + kDraco;
        if (accessors == doc_.end() || !accessors->is_array()) {
          report_.error(at, "expected the file's accessors for the decoded data");
          return false;
        }
        if (!decode_primitive(primitive, *draco, *accessors, at)) return false;
        primitive["extensions"].erase(kDraco);
        if (primitive["extensions"].empty()) primitive.erase("extensions");
      }
    }
    return true;
  }

  bool decode_primitive(Json& primitive, const Json& draco, Json& accessors, const std::string& at) {
    const auto views_it = doc_.find("bufferViews");
    const int64_t v =
        views_it != doc_.end() && views_it->is_array() ? index_at(draco, "bufferView", views_it->size()) : -1;
    uint64_t length = 0;
    const unsigned char* src = v >= 0 ? view_bytes(buffers_, (*views_it)[static_cast<size_t>(v)], length) : nullptr;
    if (!src) {
      report_.error(at + "/bufferView", "expected a buffer view inside its buffer's data");
      return false;
    }
    const Json* attributes = object_at(draco, "attributes");
    if (!attributes || !primitive.contains("attributes") || !primitive["attributes"].is_object()) {
      report_.error(at + "/attributes", "expected an object naming each attribute's Draco id");
      return false;
    }
    draco::DecoderBuffer input;
    input.Init(reinterpret_cast<const char*>(src), static_cast<size_t>(length));
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&input);
    if (!decoded.ok() || !decoded.value()) {
      report_.error(at, "its Draco data could not be decoded (" +
                            (decoded.ok() ? std::string("not a mesh") : decoded.status().error_msg_string()) + ")");
      return false;
    }
    const draco::Mesh& mesh = *decoded.value();
    const uint64_t points = mesh.num_points(), faces = mesh.num_faces();
    // Indices: always 32-bit, whatever the accessor said.
    if (primitive.contains("indices")) {
      const int64_t a = index_at(primitive, "indices", accessors.size());
      if (a < 0) {
        report_.error(at, "expected the primitive's indices accessor to exist");
        return false;
      }
      std::vector<uint32_t> indices;
      if (faces > budget_ / 12) {
        report_.error(at, "its decoded data would exceed the model's budget of bytes (--max-gltf-bytes)");
        return false;
      }
      indices.reserve(static_cast<size_t>(faces * 3));
      for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) indices.push_back(mesh.face(f)[k].value());
      uint64_t offset = 0;
      if (!append(indices.data(), indices.size() * 4, offset, at)) return false;
      Json& accessor = accessors[static_cast<size_t>(a)];
      accessor["bufferView"] = add_view(offset, indices.size() * 4);
      accessor["byteOffset"] = 0;
      accessor["componentType"] = 5125;
      accessor["count"] = indices.size();
      accessor.erase("sparse");
    }
    for (const auto& [name, id] : attributes->items()) {
      const std::string where = pointer_child(at + "/attributes", name);
      const int64_t a = primitive["attributes"].contains(name)
                            ? index_at(primitive["attributes"], name.c_str(), accessors.size())
                            : -1;
      if (!id.is_number_integer() || a < 0) {
        report_.error(where, "expected a Draco attribute id for one of the primitive's attributes");
        return false;
      }
      const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id.get<uint32_t>());
      Json& accessor = accessors[static_cast<size_t>(a)];
      const int components = accessor.is_object() ? components_of(accessor.value("type", std::string())) : 0;
      if (!attribute || components == 0 || attribute->num_components() != components) {
        report_.error(where, attribute ? "expected the accessor's type to have the Draco attribute's " +
                                             std::to_string(attribute->num_components()) + " components"
                                       : "expected an attribute id the Draco data has");
        return false;
      }
      if (points > budget_ / (4ull * components)) {
        report_.error(where, "its decoded data would exceed the model's budget of bytes (--max-gltf-bytes)");
        return false;
      }
      // As floats (what the importer reads best); normalised integers are normalised by Draco.
      std::vector<float> values(static_cast<size_t>(points * components));
      for (draco::PointIndex i(0); i < mesh.num_points(); ++i)
        if (!attribute->ConvertValue<float>(attribute->mapped_index(i), static_cast<int8_t>(components),
                                            &values[static_cast<size_t>(i.value()) * components])) {
          report_.error(where, "its Draco values could not be read as numbers");
          return false;
        }
      uint64_t offset = 0;
      if (!append(values.data(), values.size() * 4, offset, where)) return false;
      accessor["bufferView"] = add_view(offset, values.size() * 4);
      accessor["byteOffset"] = 0;
      accessor["componentType"] = 5126;
      accessor["normalized"] = false;
      accessor["count"] = points;
      accessor.erase("sparse");
    }
    return true;
  }

  size_t add_view(uint64_t offset, uint64_t length) {
    if (!doc_.contains("bufferViews") || !doc_["bufferViews"].is_array()) doc_["bufferViews"] = Json::array();
    views().push_back({{"buffer", new_buffer_index()}, {"byteOffset", offset}, {"byteLength", length}});
    return views().size() - 1;
  }

  Json& doc_;
  const std::vector<std::vector<unsigned char>>& buffers_;
  uint64_t budget_;
  Reporter& report_;
  std::vector<unsigned char> decoded_;  // the new buffer
};

}  // namespace

bool uses_compressed_geometry(const Json& document) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
    const auto it = document.find(list);
    if (it == document.end() || !it->is_array()) continue;
    for (const Json& e : *it)
      if (e.is_string() && (e == kDraco || e == kMeshopt || e == kMeshoptKhr)) return true;
  }
  return false;
}

bool decompress_geometry(Json& document, const std::vector<std::vector<unsigned char>>& buffers, uint64_t budget,
                         Reporter& report) {
  if (!document.is_object()) return false;
  if (!document.contains("buffers") || !document["buffers"].is_array()) document["buffers"] = Json::array();
  return Decoder(document, buffers, budget, report).run();
}

Json embedded_buffer(const std::vector<unsigned char>& bytes) {
  return {{"uri", "data:application/octet-stream;base64," + base64_encode(bytes)}, {"byteLength", bytes.size()}};
}

}  // namespace rt
