#include "io/scene/node_parser.h"

#include "core/csg/csg_object.h"
#include "core/transform.h"
#include "io/base/input_file.h"
#include "io/json/locate.h"
#include "io/scene/template_placement.h"

namespace rt {
namespace {

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

}  // namespace

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
