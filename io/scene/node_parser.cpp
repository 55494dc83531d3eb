#include "io/scene/node_parser.h"

#include "core/csg/csg_object.h"
#include "core/transform.h"
#include "io/base/input_file.h"
#include "io/json/locate.h"

namespace rt {
namespace {

constexpr int kMaxNodeDepth = 128;  // deeper trees are refused rather than risking the stack
const std::vector<std::string> kShapeNames = {"sphere", "cube", "plane", "cylinder", "cone"};
constexpr ShapeKind kShapeKinds[] = {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kPlane, ShapeKind::kCylinder,
                                     ShapeKind::kCone};
const std::vector<std::string> kCsgNames = {"union", "merge", "intersection", "difference"};
constexpr CsgOp kCsgOps[] = {CsgOp::kUnion, CsgOp::kMerge, CsgOp::kIntersection, CsgOp::kDifference};
constexpr std::string_view kMatrixExpected = "4 rows of 4 numbers, the last row [0, 0, 0, 1]";

std::optional<Mat4> read_matrix(const JsonReader& r, const Json& v, const std::string& ptr) {
  if (!v.is_array() || v.size() != 4) {
    r.expected(ptr, kMatrixExpected, v);
    return std::nullopt;
  }
  Mat4 m(1.0f);
  bool ok = true;
  for (size_t row = 0; row < 4; ++row) {
    const std::string row_ptr = pointer_child(ptr, row);
    if (!v[row].is_array() || v[row].size() != 4) {
      r.expected(row_ptr, "a row of 4 numbers", v[row]);
      ok = false;
      continue;
    }
    for (size_t col = 0; col < 4; ++col) {
      const auto x = read_number(r, v[row][col], pointer_child(row_ptr, col), kAnyNumber);
      if (x) m[static_cast<int>(col)][static_cast<int>(row)] = static_cast<float>(*x);  // GLM is column-major
      ok = ok && x.has_value();
    }
  }
  if (ok && (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)) {
    r.expected(pointer_child(ptr, 3), "the affine last row [0, 0, 0, 1]", v[3]);
    return std::nullopt;
  }
  return ok ? std::optional<Mat4>(m) : std::nullopt;
}

std::optional<Vec3> read_scale(const JsonReader& r, const Json& v, const std::string& ptr) {
  std::optional<Vec3> s;
  if (v.is_number()) {
    if (const auto x = read_number(r, v, ptr, kAnyNumber)) s = Vec3(static_cast<float>(*x));
  } else if (v.is_array()) {
    s = read_vec3(r, v, ptr);
  } else {
    r.expected(ptr, "a scale: one number, or [sx, sy, sz]", v);
  }
  if (s && (s->x == 0.0f || s->y == 0.0f || s->z == 0.0f)) {
    r.expected(ptr, "non-zero scale factors (a zero scale flattens the object and makes its transform singular)", v);
    return std::nullopt;
  }
  return s;
}

std::optional<uint32_t> resolve_material(NodeParseContext& ctx, const Json& v, const std::string& ptr) {
  const auto name = read_string(ctx.reader, v, ptr);
  if (!name) return std::nullopt;
  std::vector<std::string> names;
  for (uint32_t i = 0; i < ctx.materials.size(); ++i) {
    if (ctx.materials[i].name == *name) return i;
    names.push_back(ctx.materials[i].name);
  }
  std::string message = "expected the name of a material defined under /materials";
  if (names.empty()) {
    message += " (there are none)";
  } else if (names.size() <= 8) {
    message += " (";
    for (size_t i = 0; i < names.size(); ++i) message += (i ? ", \"" : "\"") + names[i] + "\"";
    message += ")";
  }
  message += ", found the undefined name \"" + *name + "\"";
  if (const auto near = closest_match(*name, names)) message += " (did you mean \"" + *near + "\"?)";
  ctx.reader.error(ptr, message);
  return std::nullopt;
}

std::optional<MeshReference> parse_mesh_reference(NodeParseContext& ctx, const Json& v, const std::string& ptr) {
  ObjectReader o(ctx.reader, v, ptr);
  MeshReference ref;
  ref.pointer = ptr;
  const auto file = o.string("file", true);
  const auto name = o.string("name");
  // One of the file's animations, by name or index (default: all of them).
  if (const Json* a = o.get("animation")) {
    if (a->is_string() && !a->get<std::string>().empty()) ref.animation = a->get<std::string>();
    else if (a->is_number_unsigned() && a->get<uint64_t>() < 1000000)
      ref.animation = std::to_string(a->get<uint64_t>());
    else ctx.reader.expected(o.child("animation"), "the name of one of the file's animations, or its index", *a);
  }
  if (const Json* overrides = o.get("materials")) {
    const std::string at = o.child("materials");
    if (!overrides->is_object()) {
      ctx.reader.expected(at, "an object from the file's material names to names under /materials", *overrides);
    } else {
      for (const auto& item : overrides->items()) {
        const std::string entry = pointer_child(at, item.key());
        if (const auto material = resolve_material(ctx, item.value(), entry))
          ref.materials.push_back(MaterialOverride{item.key(), *material, entry});
      }
    }
  }
  o.finish();
  if (!file) return std::nullopt;
  if (file->empty()) {
    ctx.reader.expected(o.child("file"), "the path of a .gltf or .glb file", v["file"]);
    return std::nullopt;
  }
  ref.file = *file;
  ref.resolved_path = resolve_path(ctx.scene_folder, *file);
  ref.mesh_name = name;
  return ref;
}

// A "csg" node's own rules, and its operands' (its children, parsed already): docs/csg.md.
void check_csg_node(const NodeParseContext& ctx, const ObjectReader& o, const NodeDescription& node) {
  const JsonReader& r = ctx.reader;
  for (const char* key : {"shape", "mesh"})
    if (o.has(key))
      r.error(o.child(key),
              std::string("expected a \"csg\" node to take its operands from \"children\", found \"") + key +
                  "\" on it (put the " + key + " in a child node)",
              Anchor::kKey);
  if (ctx.csg_depth + 1 > CsgObject::kMaxDepth)
    r.error(o.child("csg"), "expected CSG operations nested at most " + std::to_string(CsgObject::kMaxDepth) +
                                " deep, found deeper nesting");
  if (!node.csg) return;
  const size_t needed = *node.csg == CsgOp::kDifference ? 2 : 1;
  if (node.children.size() < needed) {
    const std::string what = *node.csg == CsgOp::kDifference
                                 ? "at least two operands in \"children\" (the first minus the others)"
                                 : "at least one operand in \"children\"";
    r.error(o.has("children") ? o.child("children") : o.pointer(),
            "expected a \"" + kCsgNames[static_cast<size_t>(*node.csg)] + "\" node to have " + what + ", found " +
                std::to_string(node.children.size()),
            o.has("children") ? Anchor::kValue : Anchor::kParent);
  }
  for (const NodeDescription& c : node.children) {
    if (c.shape == ShapeKind::kPlane)
      r.error(c.pointer + "/shape",
              "expected a solid as a CSG operand, found a \"plane\" (a finite square with no inside); cut with a "
              "flat \"cube\" instead");
    else if (!c.shape && !c.mesh && !c.csg)
      r.error(c.pointer,
              "expected a CSG operand: a node with a \"shape\", a \"mesh\" or a \"csg\", found a group node");
    if (!c.csg && !c.children.empty())
      r.error(c.pointer + "/children",
              "expected no children on a CSG operand (group them under a \"csg\": \"union\" node instead)",
              Anchor::kKey);
  }
}

NodeDescription parse_node(NodeParseContext& ctx, const Json& v, const std::string& ptr, int depth);

size_t subtree_size(const NodeDescription& n) {
  size_t size = 1;
  for (const NodeDescription& c : n.children) size += subtree_size(c);
  return size;
}

int subtree_height(const NodeDescription& n) {
  int height = 0;
  for (const NodeDescription& c : n.children) height = std::max(height, subtree_height(c));
  return height + 1;
}

// The template called `name`, parsed the first time it is asked for (in the folder of its file,
// with names of its own, outside any CSG); null, reported at `at`, if there is none or it is
// broken or places itself.
const NodeDescription* template_node(NodeParseContext& ctx, const std::string& name, const std::string& at, int depth) {
  const JsonReader& r = ctx.reader;
  if (const auto done = ctx.parsed_templates.find(name); done != ctx.parsed_templates.end())
    return done->second ? &*done->second : nullptr;
  const auto source = ctx.templates.find(name);
  if (source == ctx.templates.end()) {
    std::vector<std::string> names;
    for (const auto& [n, s] : ctx.templates) names.push_back(n);
    std::string message = "expected the name of a template defined under /templates";
    message += names.empty() ? " (there are none)" : names.size() <= 8 ? " (" + join_quoted(names) + ")" : "";
    message += ", found the undefined name \"" + name + "\"";
    if (const auto near = closest_match(name, names)) message += " (did you mean \"" + *near + "\"?)";
    r.error(at, message);
    return nullptr;
  }
  if (std::find(ctx.template_stack.begin(), ctx.template_stack.end(), name) != ctx.template_stack.end()) {
    std::string cycle;
    for (const std::string& t : ctx.template_stack) cycle += "\"" + t + "\" -> ";
    r.error(at, "expected templates that do not place themselves, found the cycle " + cycle + "\"" + name + "\"");
    return nullptr;
  }
  ctx.template_stack.push_back(name);
  const size_t errors_before = r.reporter().errors();
  std::string folder = source->second.folder;
  std::map<std::string, std::string> names;
  std::swap(ctx.scene_folder, folder);
  std::swap(ctx.names, names);
  const int csg_depth = std::exchange(ctx.csg_depth, 0);
  const bool csg_material = std::exchange(ctx.csg_material, false);
  ++ctx.in_template;
  NodeDescription node = parse_node(ctx, *source->second.value, source->second.pointer, depth + 1);
  --ctx.in_template;
  ctx.csg_depth = csg_depth;
  ctx.csg_material = csg_material;
  std::swap(ctx.names, names);
  std::swap(ctx.scene_folder, folder);
  ctx.template_stack.pop_back();
  std::optional<NodeDescription>& slot = ctx.parsed_templates[name];
  if (r.reporter().errors() == errors_before) slot = std::move(node);
  return slot ? &*slot : nullptr;
}

// A placed template's materials: `fill` for its shapes and CSG nodes without one, `swaps`
// (template material -> scene material) everywhere.
void override_materials(NodeDescription& n, const std::optional<uint32_t>& fill,
                        const std::map<uint32_t, uint32_t>& swaps) {
  if (!n.material && fill && (n.shape || n.csg)) n.material = fill;
  if (n.material)
    if (const auto s = swaps.find(*n.material); s != swaps.end()) n.material = s->second;
  if (n.mesh)
    for (MaterialOverride& m : n.mesh->materials)
      if (const auto s = swaps.find(m.material); s != swaps.end()) m.material = s->second;
  for (NodeDescription& c : n.children) override_materials(c, fill, swaps);
}

// Every shape of a placed template has a material, its own or its CSG's.
bool shapes_have_materials(const NodeDescription& n, bool csg_material) {
  if (n.shape && !n.material && !csg_material) return false;
  const bool covers = n.csg && (csg_material || n.material);
  for (const NodeDescription& c : n.children)
    if (!shapes_have_materials(c, n.csg ? covers : false)) return false;
  return true;
}

// Names inside a placed template: "<placement>/<name>", or none when the placement has none.
void rename_placed(NodeParseContext& ctx, NodeDescription& n, const std::string& prefix, const std::string& at) {
  if (!n.name.empty()) {
    if (prefix.empty()) {
      n.name.clear();
    } else {
      n.name = prefix + "/" + n.name;
      const auto [it, fresh] = ctx.names.emplace(n.name, at);
      if (!fresh)
        ctx.reader.error(at, "expected a unique node name, found \"" + n.name +
                                 "\" (a template's node, renamed) "
                                 "already used by " +
                                 it->second);
    }
  }
  for (NodeDescription& c : n.children) rename_placed(ctx, c, prefix, at);
}

// A node with "template": a group holding a copy of the template's node, its materials
// overridden; the geometry is not copied (a mesh is loaded once, however often placed).
void place_template(NodeParseContext& ctx, ObjectReader& o, NodeDescription& node, const Json& name_value,
                    const Json* swaps_value, int depth) {
  const JsonReader& r = ctx.reader;
  const std::string at = o.child("template");
  for (const char* key : {"shape", "mesh", "csg"})
    if (o.has(key))
      r.error(o.child(key),
              std::string("expected either \"template\" or \"") + key +
                  "\" on one node, found both (put it in the template, or in a child node)",
              Anchor::kKey);
  std::map<uint32_t, uint32_t> swaps;
  if (swaps_value) {
    const std::string swaps_at = o.child("materials");
    if (!swaps_value->is_object()) {
      r.expected(swaps_at, "an object from the template's material names to names under /materials", *swaps_value);
    } else {
      for (const auto& item : swaps_value->items()) {
        const std::string entry = pointer_child(swaps_at, item.key());
        const auto from = resolve_material(ctx, Json(item.key()), entry);
        const auto to = resolve_material(ctx, item.value(), entry);
        if (from && to) swaps[*from] = *to;
      }
    }
  }
  const auto name = read_string(r, name_value, at);
  if (!name) return;
  const NodeDescription* found = template_node(ctx, *name, at, depth);
  if (!found) return;
  const size_t size = subtree_size(*found);
  if (depth + 1 + subtree_height(*found) >= kMaxNodeDepth) {
    r.error(at, "expected at most " + std::to_string(kMaxNodeDepth) +
                    " levels of nested nodes, found deeper nesting (templates placed inside templates)");
    return;
  }
  if (ctx.nodes + size > ctx.max_nodes) {
    r.error(at, "expected at most " + std::to_string(ctx.max_nodes) +
                    " nodes in a scene, found more once templates are placed (docs/errors-and-limits.md, \"Limits\")");
    ctx.nodes = ctx.max_nodes + 1;  // stops the parse
    return;
  }
  ctx.nodes += size;
  NodeDescription copy = *found;
  override_materials(copy, node.material, swaps);
  if (ctx.in_template == 0 && !shapes_have_materials(copy, ctx.csg_material)) {
    r.error(o.has("material") ? o.child("material") : at,
            "expected a material for every shape of template \"" + *name +
                "\": give this node \"material\" (it goes to the template's shapes that have none)",
            o.has("material") ? Anchor::kValue : Anchor::kKey);
  }
  rename_placed(ctx, copy, node.name, o.pointer());
  node.material.reset();  // the placement is a group
  node.children.insert(node.children.begin(), std::move(copy));
}

NodeDescription parse_node(NodeParseContext& ctx, const Json& v, const std::string& ptr, int depth) {
  const JsonReader& r = ctx.reader;
  NodeDescription node;
  node.pointer = ptr;
  ObjectReader o(r, v, ptr);
  if (const auto name = o.string("name")) {
    node.name = *name;
    const auto [it, fresh] = ctx.names.emplace(*name, ptr);
    if (!fresh)
      r.error(o.child("name"), "expected a unique node name, found \"" + *name + "\" already used by " + it->second);
  }
  if (const Json* t = o.get("transform"))
    node.transform = parse_transform(r, *t, o.child("transform")).value_or(NodeTransform{});
  if (const Json* s = o.get("shape")) {
    if (const auto k = read_choice(r, *s, o.child("shape"), kShapeNames)) node.shape = kShapeKinds[*k];
  }
  if (const Json* m = o.get("mesh")) node.mesh = parse_mesh_reference(ctx, *m, o.child("mesh"));
  const Json* material = o.get("material");
  if (material) node.material = resolve_material(ctx, *material, o.child("material"));
  const Json* placed = o.get("template");
  const Json* swaps = placed ? o.get("materials") : nullptr;
  if (const Json* c = o.get("csg")) {
    if (const auto k = read_choice(r, *c, o.child("csg"), kCsgNames)) node.csg = kCsgOps[*k];
  }
  if (const Json* children = o.get("children")) {
    if (depth + 1 >= kMaxNodeDepth) {
      r.error(o.child("children"),
              "expected at most " + std::to_string(kMaxNodeDepth) + " levels of nested nodes, found deeper nesting");
    } else {
      // A CSG node's children are its operands; any other node's children are not, even inside a CSG.
      const int csg_depth = ctx.csg_depth;
      const bool csg_material = ctx.csg_material;
      ctx.csg_depth = o.has("csg") ? csg_depth + 1 : 0;
      ctx.csg_material = o.has("csg") && (csg_material || material);
      node.children = parse_nodes(ctx, *children, o.child("children"), depth + 1);
      ctx.csg_depth = csg_depth;
      ctx.csg_material = csg_material;
    }
  }
  o.finish();
  if (!o.valid()) return node;
  if (placed) {
    place_template(ctx, o, node, *placed, swaps, depth);
    return node;
  }
  if (o.has("csg")) check_csg_node(ctx, o, node);
  const bool operand = ctx.csg_depth > 0;
  if (o.has("shape") && o.has("mesh"))
    r.error(o.child("mesh"), "expected either \"shape\" or \"mesh\" on one node, found both (use child nodes)",
            Anchor::kKey);
  if (o.has("shape") && !material && !(operand && ctx.csg_material) && ctx.in_template == 0)
    r.error(o.child("material"), "missing required key \"material\"; expected the name of a material for the shape",
            Anchor::kParent);
  if (material && !o.has("shape") && !o.has("mesh") && !o.has("csg"))
    r.error(o.child("material"),
            "expected a material only on a node with a \"shape\", a \"mesh\" or a \"csg\", found one on a group "
            "node",
            Anchor::kKey);
  return node;
}

}  // namespace

std::optional<NodeTransform> parse_transform(const JsonReader& r, const Json& value, const std::string& ptr) {
  ObjectReader o(r, value, ptr);
  std::optional<NodeTransform> result;
  if (const Json* m = o.get("matrix")) {
    for (const char* key : {"translate", "rotate", "scale"}) {
      if (o.get(key))
        r.error(o.child(key), "expected either \"matrix\" or translate/rotate/scale, found both", Anchor::kKey);
    }
    if (const auto matrix = read_matrix(r, *m, o.child("matrix"))) result = NodeTransform{Trs{}, matrix};
    if (result && !make_transform(result->local())) {
      r.error(o.child("matrix"),
              "expected an invertible matrix, found a singular one (it flattens space: no inverse, no normals)");
      result.reset();
    }
  } else {
    const auto t = o.vec3("translate");
    const auto rot = o.vec3("rotate");
    std::optional<Vec3> s;
    if (const Json* sv = o.get("scale")) s = read_scale(r, *sv, o.child("scale"));
    const bool bad = (o.has("translate") && !t) || (o.has("rotate") && !rot) || (o.has("scale") && !s);
    if (!bad)
      result = NodeTransform{
          Trs{t.value_or(Vec3(0.0f)), euler_degrees_to_quat(rot.value_or(Vec3(0.0f))), s.value_or(Vec3(1.0f))}, {}};
    if (result && !make_transform(result->local())) {
      r.error(ptr, "expected an invertible transform, found a singular one (scale factors too far apart)");
      result.reset();
    }
  }
  o.finish();
  return result;
}

std::vector<NodeDescription> parse_nodes(NodeParseContext& ctx, const Json& value, const std::string& pointer,
                                         int depth) {
  std::vector<NodeDescription> nodes;
  if (!value.is_array()) {
    ctx.reader.expected(pointer, "an array of nodes", value);
    return nodes;
  }
  for (size_t i = 0; i < value.size() && ctx.nodes <= ctx.max_nodes; ++i) {
    if (++ctx.nodes > ctx.max_nodes) {
      ctx.reader.error(pointer_child(pointer, i),
                       "expected at most " + std::to_string(ctx.max_nodes) +
                           " nodes in a scene, found more (docs/errors-and-limits.md, \"Limits\")");
      break;
    }
    nodes.push_back(parse_node(ctx, value[i], pointer_child(pointer, i), depth));
  }
  return nodes;
}

}  // namespace rt
