#include "io/assemble/csg_operands.h"

namespace rt {
namespace {

class TemplateMaker {
 public:
  TemplateMaker(const CsgSource& source, std::vector<SceneNode>& nodes, Reporter& report)
      : source_(source), nodes_(nodes), report_(report) {}

  bool add(const NodeDescription& d, std::optional<uint32_t> material) {
    const auto found = source_.scene_index.find(&d);
    if (found == source_.scene_index.end()) return false;  // not added (a limit stopped the build)
    const uint32_t index = found->second;
    const uint32_t at = static_cast<uint32_t>(out_.nodes.size());
    out_.nodes.push_back(CsgTemplateNode{});
    CsgTemplateNode n;
    n.node = index;
    bool ok = true;
    if (d.csg) {
      n.op = *d.csg;
      const std::optional<uint32_t> inherited = d.material ? d.material : material;
      for (const NodeDescription& c : d.children) ok = add(c, inherited) && ok;
    } else {
      n.leaf = true;
      SceneNode& carrier = nodes_[index];
      if (carrier.shape) {
        n.shape = carrier.shape;
        n.material = d.material ? *d.material : material.value_or(0);
        carrier.shape.reset();
      }
      if (d.mesh) ok = take_meshes(d, index, n);
    }
    n.end = static_cast<uint32_t>(out_.nodes.size());
    out_.nodes[at] = std::move(n);
    return ok;
  }

  CsgTemplate take() { return std::move(out_); }

 private:
  // The primitives of the operand node and of every node a glTF file grafted under it.
  bool take_meshes(const NodeDescription& d, uint32_t index, CsgTemplateNode& n) {
    std::vector<bool> below(nodes_.size() - index, false);
    below[0] = true;
    std::vector<const TriangleMesh*> parts;
    size_t open_edges = 0;
    for (uint32_t j = index; j < nodes_.size(); ++j) {
      SceneNode& node = nodes_[j];
      if (j > index) {
        if (node.parent < static_cast<int32_t>(index)) break;  // past the subtree
        if (!below[static_cast<size_t>(node.parent) - index]) continue;
        below[j - index] = true;
      }
      if (node.meshes.empty()) continue;
      if (!node.instancing.empty()) {
        report_.error(d.mesh->pointer,
                      "expected a closed mesh as a CSG operand, found \"" + d.mesh->file +
                          "\" placing copies with EXT_mesh_gpu_instancing (make each copy an operand)");
        return false;
      }
      parts.clear();
      for (const NodeMesh& nm : node.meshes) {
        n.meshes.push_back(CsgMeshPart{j, nm.mesh, nm.material});
        parts.push_back(&source_.assets.meshes[nm.mesh].mesh);
      }
      open_edges += count_open_edges(parts);  // each glTF mesh closed on its own, all its primitives together
      node.meshes.clear();
    }
    if (open_edges == 0) return true;
    const std::string name = d.name.empty() ? "" : "node \"" + d.name + "\": ";
    report_.error(d.mesh->pointer, name + "expected a closed (watertight) mesh as a CSG operand, found \"" +
                                       d.mesh->file + "\" with " + std::to_string(open_edges) + " open edge" +
                                       (open_edges == 1 ? "" : "s") +
                                       " (edges not shared by two triangles: a CSG operand needs an inside)");
    return false;
  }

  const CsgSource& source_;
  std::vector<SceneNode>& nodes_;
  Reporter& report_;
  CsgTemplate out_;
};

}  // namespace

std::optional<CsgTemplate> make_csg_template(const CsgSource& source, std::vector<SceneNode>& nodes, Reporter& report) {
  TemplateMaker maker(source, nodes, report);
  if (!maker.add(source.root, std::nullopt)) return std::nullopt;
  return maker.take();
}

}  // namespace rt
