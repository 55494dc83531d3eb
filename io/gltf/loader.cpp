#include "io/gltf/loader.h"

#include <cmath>
#include <filesystem>

#include <tiny_gltf.h>

#include "io/base/input_file.h"
#include "io/gltf/accessor.h"
#include "io/gltf/animation.h"
#include "io/gltf/extras.h"
#include "io/gltf/file.h"
#include "io/gltf/images.h"
#include "io/gltf/materials.h"
#include "io/gltf/mesh_budget.h"
#include "io/gltf/node_parts.h"

namespace rt {
namespace {

using std::to_string;

// Triangle list from a primitive's index stream in triangle, strip or fan mode, in the vertex
// order the glTF 2.0 specification gives (3.7.2.1): strip triangle k is (v_k, v_{k+1+k%2},
// v_{k+2-k%2}), which keeps one winding; fan triangle k is (v_{k+1}, v_{k+2}, v_0).
std::vector<uint32_t> to_triangle_list(std::vector<uint32_t> v, int mode) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    v.resize(v.size() / 3 * 3);
    return v;
  }
  std::vector<uint32_t> out;
  out.reserve(v.size() >= 2 ? 3 * (v.size() - 2) : 0);
  for (size_t k = 0; k + 2 < v.size(); ++k) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) out.insert(out.end(), {v[k], v[k + 1 + k % 2], v[k + 2 - k % 2]});
    else out.insert(out.end(), {v[k + 1], v[k + 2], v[0]});
  }
  return out;
}

class Importer {
 public:
  Importer(const tinygltf::Model& model, const LoadLimits& limits, LimitUsage& usage, ImportedModel& out,
           Reporter& report)
      : model_(model),
        limits_(limits),
        usage_(usage),
        out_(out),
        report_(report),
        imported_(model.meshes.size(), false) {
    out_.meshes.resize(model.meshes.size());
  }

  // Imports mesh `index` once (the first time a node uses it).
  bool import_mesh(size_t index) {
    if (!imported_[index]) {
      imported_[index] = true;
      const tinygltf::Mesh& mesh = model_.meshes[index];
      for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        const std::string where = "mesh " + to_string(index) + (mesh.name.empty() ? "" : " (\"" + mesh.name + "\")") +
                                  " primitive " + to_string(p);
        const std::string at = "/meshes/" + to_string(index) + "/primitives/" + to_string(p);
        if (!import_primitive(mesh.primitives[p], where, at, out_.meshes[index])) return false;
      }
    }
    return true;
  }

  // A node of its own carrying mesh `index` (no node tree: a mesh asked for by name, or a file
  // without scenes).
  bool add_mesh_node(size_t index) {
    if (!import_mesh(index)) return false;
    ImportedNode node;
    node.name = model_.meshes[index].name;
    node.mesh = static_cast<int32_t>(index);
    out_.nodes.push_back(std::move(node));
    return true;
  }

 private:
  bool fail(const std::string& pointer, const std::string& message) {
    report_.error(pointer, message);
    return false;
  }

  // The primitive's vertices and triangles, from its accessors' counts, against what the scene
  // has left: checked before anything is read, so that many primitives sharing one huge
  // accessor stop at the first that does not fit.
  bool reserve(MeshCost cost, const std::string& where, const std::string& at) {
    const uint64_t vertices = cost.vertices, triangles = cost.triangles;
    const auto over = [&](const char* what, uint64_t limit, uint64_t used, uint64_t wanted) {
      report_.over_limit(at, where + ": expected at most " + to_string(limit) + " " + what +
                                 " in a scene's meshes, found " + to_string(wanted) + " here" +
                                 (used ? " after " + to_string(used) + " in the meshes before it" : std::string()));
      return false;
    };
    if (vertices > limits_.vertices || usage_.vertices > limits_.vertices - vertices)
      return over("vertices", limits_.vertices, usage_.vertices, vertices);
    if (triangles > limits_.triangles || usage_.triangles > limits_.triangles - triangles)
      return over("triangles", limits_.triangles, usage_.triangles, triangles);
    usage_.vertices += vertices;
    usage_.triangles += triangles;
    return true;
  }

  bool import_primitive(const tinygltf::Primitive& prim, const std::string& where, const std::string& at,
                        std::vector<ImportedPrimitive>& out) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      report_.warning(at + "/mode", where + ": points and lines are not rendered; primitive skipped");
      return true;
    }
    const auto pos_it = prim.attributes.find("POSITION");
    if (pos_it == prim.attributes.end()) {
      report_.warning(at + "/attributes", where + ": no POSITION attribute; primitive skipped");
      return true;
    }
    // Who reads an attribute's accessor: its message context and the pointer naming it.
    const auto use = [&](const std::string& attribute) {
      return AccessorUse{report_, where + " " + attribute + ": ", at + "/attributes/" + attribute};
    };
    const auto accessor_at = [](int index) { return "/accessors/" + to_string(index); };
    ImportedPrimitive ip;
    ip.material = prim.material;
    if (prim.material >= static_cast<int>(model_.materials.size()))
      return fail(at + "/material", where + ": material " + to_string(prim.material) + " does not exist");
    if (!reserve(primitive_cost(model_, prim), where, at)) return false;
    std::vector<float> raw;
    if (!read_float_accessor(model_, pos_it->second, 3, limits_.vertices, raw, use("POSITION"))) return false;
    const size_t n = raw.size() / 3;
    ip.mesh.positions.resize(n);
    for (size_t i = 0; i < n; ++i) {
      ip.mesh.positions[i] = Vec3(raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]);
      if (!is_finite(ip.mesh.positions[i]))
        return fail(accessor_at(pos_it->second),
                    where + " POSITION: vertex " + to_string(i) + " is not a finite point in single precision");
    }
    // Another attribute's accessor, read as `components` floats a vertex, as many as POSITION has.
    const auto read_attribute = [&](int accessor, const std::string& name, int components) {
      if (!read_float_accessor(model_, accessor, components, limits_.vertices, raw, use(name))) return false;
      if (raw.size() / static_cast<size_t>(components) == n) return true;
      return fail(accessor_at(accessor) + "/count", where + ": " + name + " and POSITION counts differ");
    };
    if (const auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
      if (!read_attribute(it->second, "NORMAL", 3)) return false;
      ip.mesh.normals.resize(n);
      for (size_t i = 0; i < n; ++i) {
        const Vec3 v(raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]);
        const float len = glm::length(v);
        ip.mesh.normals[i] = (len > 0.0f && std::isfinite(len)) ? v / len : Vec3(0.0f);  // zero: use the face normal
      }
    }
    for (const auto& [name, uvs] : {std::pair{"TEXCOORD_0", &ip.mesh.uvs}, std::pair{"TEXCOORD_1", &ip.mesh.uvs1}}) {
      const auto it = prim.attributes.find(name);
      if (it == prim.attributes.end()) continue;
      if (!read_attribute(it->second, name, 2)) return false;
      uvs->resize(n);
      for (size_t i = 0; i < n; ++i) (*uvs)[i] = Vec2(raw[2 * i], raw[2 * i + 1]);
    }
    if (const auto it = prim.attributes.find("COLOR_0"); it != prim.attributes.end()) {
      // VEC3 or VEC4, float or normalised integers: linear colours (alpha 1 with VEC3).
      const int components = it->second >= 0 && static_cast<size_t>(it->second) < model_.accessors.size() &&
                                     model_.accessors[static_cast<size_t>(it->second)].type == TINYGLTF_TYPE_VEC3
                                 ? 3
                                 : 4;
      if (!read_attribute(it->second, "COLOR_0", components)) return false;
      ip.mesh.colors.resize(n);
      for (size_t i = 0; i < n; ++i) {
        const float* c = &raw[static_cast<size_t>(components) * i];
        const Vec4 v(c[0], c[1], c[2], components == 4 ? c[3] : 1.0f);
        ip.mesh.colors[i] = std::isfinite(v.x + v.y + v.z + v.w) ? glm::clamp(v, Vec4(0.0f), Vec4(1.0f)) : Vec4(1.0f);
      }
    }
    if (const auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end()) {
      if (!read_attribute(it->second, "TANGENT", 4)) return false;
      ip.mesh.tangents.resize(n);
      for (size_t i = 0; i < n; ++i) {
        const Vec3 t(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2]);
        const float len = glm::length(t);
        // A zero or broken tangent falls back to the frame from the UVs (w = 0 means none).
        ip.mesh.tangents[i] = len > 0.0f && std::isfinite(len) && std::isfinite(raw[4 * i + 3])
                                  ? Vec4(t / len, raw[4 * i + 3] < 0.0f ? -1.0f : 1.0f)
                                  : Vec4(0.0f);
      }
    }
    std::vector<uint32_t> indices;
    if (prim.indices >= 0) {
      // A strip or fan of k indices makes k - 2 triangles; a list, k / 3.
      const uint64_t max_indices = mode == TINYGLTF_MODE_TRIANGLES ? 3 * limits_.triangles : limits_.triangles + 2;
      if (!read_index_accessor(model_, prim.indices, max_indices, n, indices,
                               AccessorUse{report_, where + " indices: ", at + "/indices"}))
        return false;
    } else {
      indices.resize(n);
      for (size_t i = 0; i < n; ++i) indices[i] = static_cast<uint32_t>(i);
    }
    ip.mesh.indices = to_triangle_list(std::move(indices), mode);
    if (ip.mesh.indices.empty()) {
      report_.warning(at, where + ": no complete triangle; primitive skipped");
      return true;
    }
    out.push_back(std::move(ip));
    return true;
  }

  const tinygltf::Model& model_;
  const LoadLimits& limits_;
  LimitUsage& usage_;
  ImportedModel& out_;
  Reporter& report_;
  std::vector<bool> imported_;
};

// The default scene's node forest, walked without recursion. glTF requires the nodes to form
// disjoint trees: no node with two parents, no cycles, roots that are nobody's child. Checking
// that first bounds the walk by the number of nodes (a node listed twice as a child would
// otherwise double the work at every level).
// node_map receives, per file node, its index in out.nodes (-1: not in the scene).
bool place_scene(const tinygltf::Model& model, const tinygltf::Scene& scene, const LoadLimits& limits,
                 const std::string& scene_at, Importer& importer, ImportedModel& out, std::vector<int32_t>& node_map,
                 Reporter& report) {
  const size_t count = model.nodes.size();
  const auto fail = [&](const std::string& pointer, const std::string& message) {
    report.error(pointer, message);
    return false;
  };
  if (count > limits.nodes)
    return fail("/nodes",
                "it has " + to_string(count) + " nodes, more than the " + to_string(limits.nodes) + " rtcli accepts");
  std::vector<int> parent(count, -1);
  for (size_t i = 0; i < count; ++i) {
    const std::vector<int>& children = model.nodes[i].children;
    for (size_t c = 0; c < children.size(); ++c) {
      const int child = children[c];
      const std::string child_at = "/nodes/" + to_string(i) + "/children/" + to_string(c);
      if (child < 0 || static_cast<size_t>(child) >= count)
        return fail(child_at, "node " + to_string(i) + " lists child " + to_string(child) + ", which does not exist");
      if (static_cast<size_t>(child) == i || parent[static_cast<size_t>(child)] >= 0)
        return fail(child_at, "node " + to_string(child) + " is a child of node " + to_string(i) +
                                  (static_cast<size_t>(child) == i
                                       ? " itself"
                                       : " and of node " + to_string(parent[static_cast<size_t>(child)])) +
                                  "; glTF requires every node to have at most one parent");
      parent[static_cast<size_t>(child)] = static_cast<int>(i);
    }
  }
  std::vector<bool> is_root(count, false);
  for (size_t r = 0; r < scene.nodes.size(); ++r) {
    const int root = scene.nodes[r];
    const std::string root_at = scene_at + "/nodes/" + to_string(r);
    if (root < 0 || static_cast<size_t>(root) >= count)
      return fail(root_at, "the scene lists node " + to_string(root) + ", which does not exist");
    if (parent[static_cast<size_t>(root)] >= 0 || is_root[static_cast<size_t>(root)])
      return fail(root_at, "the scene lists node " + to_string(root) +
                               (is_root[static_cast<size_t>(root)]
                                    ? " twice"
                                    : ", which is a child of node " + to_string(parent[static_cast<size_t>(root)])) +
                               "; glTF requires the scene's nodes to be distinct roots");
    is_root[static_cast<size_t>(root)] = true;
  }
  // Every node is reached at most once: from its only parent, or as a root without one. Nodes in
  // a cycle have their parents inside the cycle, so no root reaches them.
  struct Item {
    int node;
    int32_t parent;  // in ImportedModel::nodes
  };
  std::vector<Item> stack;
  for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it) stack.push_back(Item{*it, -1});
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(item.node)];
    const std::string node_at = "/nodes/" + to_string(item.node);
    if (node.mesh >= static_cast<int>(model.meshes.size()))
      return fail(node_at + "/mesh",
                  "node " + to_string(item.node) + " uses mesh " + to_string(node.mesh) + ", which does not exist");
    if (node.mesh >= 0 && !importer.import_mesh(static_cast<size_t>(node.mesh))) return false;
    ImportedNode imported;
    imported.name = node.name;
    imported.parent = item.parent;
    imported.mesh = node.mesh;
    imported.gltf_index = item.node;
    read_node_transform(node, imported);
    if (node.mesh >= 0 && !import_instancing(model, node, node_at, limits, imported, report)) return false;
    const auto index = static_cast<int32_t>(out.nodes.size());
    if (!import_camera(model, node, node_at, index, out, report) ||
        !import_light(model, node, node_at, index, out, report))
      return false;
    if (auto area = area_light_from_extras(node.extras, "node \"" + node.name + "\"", node_at, report))
      out.lights.push_back(LightPlacement{*area, index});
    node_map[static_cast<size_t>(item.node)] = index;
    out.nodes.push_back(std::move(imported));
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back(Item{*it, index});
  }
  return true;
}

}  // namespace

std::optional<ImportedModel> import_gltf_bytes(const std::vector<unsigned char>& bytes, const std::string& base_dir,
                                               const GltfSelection& selection, const LoadLimits& limits,
                                               LimitUsage& usage, Reporter& report, ImportError& import_error) {
  GltfFile file = parse_gltf(bytes, base_dir, limits, report);
  ImportedModel out;
  out.files = std::move(file.files);
  if (!file.model) return std::nullopt;
  const tinygltf::Model& model = *file.model;
  ImageDecoder images(model, base_dir, limits, usage, out, report);
  if (!images.fit_in_budget()) return std::nullopt;
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    const std::string where = "material " + to_string(i) + (m.name.empty() ? "" : " (\"" + m.name + "\")");
    const std::string at = "/materials/" + to_string(i);
    out.materials.push_back(import_material(m, images, where, at));
    apply_material_extras(m.extras, images, where, at, out.materials.back(), report);
    out.material_names.push_back(m.name);
    if (images.failed()) return std::nullopt;
  }
  images.finish(out.materials, limits.decode_threads);
  const int scene = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
  if (!meshes_fit(model, meshes_used(model, selection.mesh, scene), limits, usage, report)) return std::nullopt;
  Importer importer(model, limits, usage, out, report);

  if (selection.mesh) {
    std::string names;
    for (size_t i = 0; i < model.meshes.size(); ++i) {
      if (model.meshes[i].name == *selection.mesh) {
        if (!importer.add_mesh_node(i)) return std::nullopt;
        return out;
      }
      if (i < 20) names += (names.empty() ? "\"" : ", \"") + model.meshes[i].name + "\"";
    }
    if (model.meshes.size() > 20) names += ", ...";
    import_error.unknown_mesh = true;
    import_error.message = "its meshes are " + (names.empty() ? std::string("none") : names);
    return std::nullopt;
  }

  if (scene >= static_cast<int>(model.scenes.size())) {
    report.error("/scene", "its default scene " + to_string(scene) + " does not exist");
    return std::nullopt;
  }
  if (scene < 0) {
    for (size_t i = 0; i < model.meshes.size(); ++i)
      if (!importer.add_mesh_node(i)) return std::nullopt;
    return out;
  }
  const size_t errors_before_world = report.errors();
  out.world = world_from_extras(model.scenes[static_cast<size_t>(scene)].extras, base_dir, limits.outside_files,
                                "/scenes/" + to_string(scene), report);
  if (report.errors() > errors_before_world) return std::nullopt;
  std::vector<int32_t> node_map(model.nodes.size(), -1);
  if (!place_scene(model, model.scenes[static_cast<size_t>(scene)], limits, "/scenes/" + to_string(scene), importer,
                   out, node_map, report))
    return std::nullopt;
  if (!import_animations(model, node_map, selection.animation, limits, usage, out, report, import_error))
    return std::nullopt;
  return out;
}

std::vector<ModelPlacement> placements(const ImportedModel& model) {
  std::vector<Mat4> world(model.nodes.size());
  std::vector<ModelPlacement> out;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const ImportedNode& n = model.nodes[i];
    const Mat4 local = n.matrix ? *n.matrix : n.trs.matrix();
    world[i] = n.parent >= 0 ? world[static_cast<size_t>(n.parent)] * local : local;
    if (n.mesh < 0) continue;
    if (n.instancing.empty()) out.push_back(ModelPlacement{static_cast<size_t>(n.mesh), world[i]});
    for (const Mat4& copy : n.instancing) out.push_back(ModelPlacement{static_cast<size_t>(n.mesh), world[i] * copy});
  }
  return out;
}

std::optional<ImportedModel> import_gltf(const std::string& path, const GltfSelection& selection,
                                         const LoadLimits& limits, LimitUsage& usage, Reporter& report,
                                         ImportError& error) {
  std::string why;
  auto bytes = read_input_bytes(path, limits.gltf_total_bytes, why);
  if (!bytes) {
    report.error("", why);
    return std::nullopt;
  }
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  auto model = import_gltf_bytes(*bytes, base_dir.empty() ? "." : base_dir, selection, limits, usage, report, error);
  if (model) model->files.insert(model->files.begin(), path);
  return model;
}

}  // namespace rt
