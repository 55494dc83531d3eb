#include "io/gltf_loader.h"

#include <filesystem>
#include <fstream>
#include <functional>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "io/gltf_accessor.h"
#include "io/json_document.h"
#include "io/pbr_to_phong.h"

namespace rt {
namespace {

// Textures are not decoded here (texture mapping loads its own images); accept every image.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

bool is_binary_gltf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && std::string(magic, 4) == "glTF";
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

Mat4 node_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    Mat4 m;
    for (int i = 0; i < 16; ++i)
      glm::value_ptr(m)[i] = static_cast<float>(node.matrix[static_cast<size_t>(i)]);  // column-major
    return m;
  }
  Mat4 m(1.0f);
  if (node.translation.size() == 3)
    m = glm::translate(m, Vec3(static_cast<float>(node.translation[0]), static_cast<float>(node.translation[1]),
                               static_cast<float>(node.translation[2])));
  if (node.rotation.size() == 4)  // glTF quaternions are (x, y, z, w); GLM's constructor takes w first
    m *= glm::mat4_cast(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                  static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
  if (node.scale.size() == 3)
    m = glm::scale(m, Vec3(static_cast<float>(node.scale[0]), static_cast<float>(node.scale[1]),
                           static_cast<float>(node.scale[2])));
  return m;
}

// Triangle list from a primitive's index stream in triangle, strip or fan mode, in the vertex
// order the glTF 2.0 specification gives (3.7.2.1): strip triangle k is (v_k, v_{k+1+k%2},
// v_{k+2-k%2}), which keeps one winding; fan triangle k is (v_{k+1}, v_{k+2}, v_0).
std::vector<uint32_t> to_triangle_list(const std::vector<uint32_t>& v, int mode) {
  if (mode == TINYGLTF_MODE_TRIANGLES)
    return std::vector<uint32_t>(v.begin(), v.begin() + static_cast<long>(v.size() / 3 * 3));
  std::vector<uint32_t> out;
  for (size_t k = 0; k + 2 < v.size(); ++k) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) out.insert(out.end(), {v[k], v[k + 1 + k % 2], v[k + 2 - k % 2]});
    else out.insert(out.end(), {v[k + 1], v[k + 2], v[0]});
  }
  return out;
}

bool import_primitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& where,
                      ImportedModel& out_model, std::vector<ImportedPrimitive>& out, std::string& error) {
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    out_model.warnings.push_back(where + ": points and lines are not rendered; primitive skipped");
    return true;
  }
  const auto pos_it = prim.attributes.find("POSITION");
  if (pos_it == prim.attributes.end()) {
    out_model.warnings.push_back(where + ": no POSITION attribute; primitive skipped");
    return true;
  }
  ImportedPrimitive ip;
  ip.material = prim.material;
  if (prim.material >= static_cast<int>(model.materials.size())) {
    error = where + ": material " + std::to_string(prim.material) + " does not exist";
    return false;
  }
  std::vector<double> raw;
  if (!read_accessor(model, pos_it->second, 3, raw, error)) return (error = where + " POSITION: " + error), false;
  const size_t n = raw.size() / 3;
  ip.mesh.positions.resize(n);
  for (size_t i = 0; i < n; ++i) {
    ip.mesh.positions[i] =
        Vec3(static_cast<float>(raw[3 * i]), static_cast<float>(raw[3 * i + 1]), static_cast<float>(raw[3 * i + 2]));
    if (!is_finite(ip.mesh.positions[i])) {
      error = where + " POSITION: vertex " + std::to_string(i) + " is not a finite point";
      return false;
    }
  }
  if (const auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
    if (!read_accessor(model, it->second, 3, raw, error)) return (error = where + " NORMAL: " + error), false;
    if (raw.size() / 3 != n) return (error = where + ": NORMAL and POSITION counts differ"), false;
    ip.mesh.normals.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const Vec3 v(static_cast<float>(raw[3 * i]), static_cast<float>(raw[3 * i + 1]),
                   static_cast<float>(raw[3 * i + 2]));
      const float len = glm::length(v);
      ip.mesh.normals[i] = (len > 0.0f && std::isfinite(len)) ? v / len : Vec3(0.0f);  // zero: use the face normal
    }
  }
  if (const auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
    if (!read_accessor(model, it->second, 2, raw, error)) return (error = where + " TEXCOORD_0: " + error), false;
    if (raw.size() / 2 != n) return (error = where + ": TEXCOORD_0 and POSITION counts differ"), false;
    ip.mesh.uvs.resize(n);
    for (size_t i = 0; i < n; ++i)
      ip.mesh.uvs[i] = Vec2(static_cast<float>(raw[2 * i]), static_cast<float>(raw[2 * i + 1]));
  }
  std::vector<uint32_t> indices;
  if (prim.indices >= 0) {
    if (!read_indices(model, prim.indices, n, indices, error)) return (error = where + " indices: " + error), false;
  } else {
    indices.resize(n);
    for (size_t i = 0; i < n; ++i) indices[i] = static_cast<uint32_t>(i);
  }
  ip.mesh.indices = to_triangle_list(indices, mode);
  if (ip.mesh.indices.empty()) {
    out_model.warnings.push_back(where + ": no complete triangle; primitive skipped");
    return true;
  }
  out.push_back(std::move(ip));
  return true;
}

bool import_mesh(const tinygltf::Model& model, size_t mesh_index, ImportedModel& out, std::string& error) {
  const tinygltf::Mesh& mesh = model.meshes[mesh_index];
  std::vector<ImportedPrimitive>& prims = out.meshes[mesh_index];
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const std::string where = "mesh " + std::to_string(mesh_index) +
                              (mesh.name.empty() ? "" : " (\"" + mesh.name + "\")") + " primitive " + std::to_string(p);
    if (!import_primitive(model, mesh.primitives[p], where, out, prims, error)) return false;
  }
  return true;
}

}  // namespace

std::optional<ImportedModel> import_gltf(const std::string& path, const std::optional<std::string>& mesh_name,
                                         ImportError& import_error) {
  std::string& error = import_error.message;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    error = "file not found";
    return std::nullopt;
  }
  if (std::filesystem::is_directory(path, ec)) {
    error = "is a directory, not a file";
    return std::nullopt;
  }
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skip_image, nullptr);
  std::string err, warn;
  const bool ok = is_binary_gltf(path) ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                                       : loader.LoadASCIIFromFile(&model, &err, &warn, path);
  if (!ok) {
    error = err.empty() ? "not a readable glTF file" : clean_parser_message(trim(err));
    return std::nullopt;
  }
  ImportedModel out;
  if (!warn.empty()) out.warnings.push_back(trim(warn));
  for (const tinygltf::Material& m : model.materials) {
    const auto& pbr = m.pbrMetallicRoughness;
    const Vec3 base = pbr.baseColorFactor.size() >= 3
                          ? Vec3(static_cast<float>(pbr.baseColorFactor[0]), static_cast<float>(pbr.baseColorFactor[1]),
                                 static_cast<float>(pbr.baseColorFactor[2]))
                          : Vec3(1.0f);
    out.materials.push_back(
        pbr_to_phong(base, static_cast<float>(pbr.metallicFactor), static_cast<float>(pbr.roughnessFactor)));
  }
  out.meshes.resize(model.meshes.size());

  if (mesh_name) {
    std::string names;
    for (size_t i = 0; i < model.meshes.size(); ++i) {
      if (model.meshes[i].name == *mesh_name) {
        if (!import_mesh(model, i, out, error)) return std::nullopt;
        out.instances.push_back(MeshInstance{i, Mat4(1.0f)});
        return out;
      }
      names += (names.empty() ? "\"" : ", \"") + model.meshes[i].name + "\"";
    }
    import_error.unknown_mesh = true;
    error = "its meshes are " + (names.empty() ? std::string("none") : names);
    return std::nullopt;
  }

  std::vector<bool> imported(model.meshes.size(), false);
  const auto place = [&](size_t mesh, const Mat4& m) -> bool {
    if (!imported[mesh] && !import_mesh(model, mesh, out, error)) return false;
    imported[mesh] = true;
    out.instances.push_back(MeshInstance{mesh, m});
    return true;
  };
  const int scene = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
  if (scene < 0 || scene >= static_cast<int>(model.scenes.size())) {
    for (size_t i = 0; i < model.meshes.size(); ++i)
      if (!place(i, Mat4(1.0f))) return std::nullopt;
    return out;
  }
  // Depth-first over the node tree; the depth limit also stops cycles in malformed files.
  std::function<bool(int, const Mat4&, int)> visit = [&](int node_index, const Mat4& parent, int depth) -> bool {
    if (node_index < 0 || node_index >= static_cast<int>(model.nodes.size()) || depth > 256) {
      error =
          "node " + std::to_string(node_index) + (depth > 256 ? " is nested too deeply (a cycle?)" : " does not exist");
      return false;
    }
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(node_index)];
    const Mat4 world = parent * node_matrix(node);
    if (node.mesh >= static_cast<int>(model.meshes.size())) {
      error =
          "node " + std::to_string(node_index) + " uses mesh " + std::to_string(node.mesh) + ", which does not exist";
      return false;
    }
    if (node.mesh >= 0 && !place(static_cast<size_t>(node.mesh), world)) return false;
    for (const int child : node.children)
      if (!visit(child, world, depth + 1)) return false;
    return true;
  };
  for (const int root : model.scenes[static_cast<size_t>(scene)].nodes)
    if (!visit(root, Mat4(1.0f), 0)) return std::nullopt;
  return out;
}

}  // namespace rt
