#include "io/scene/template_placement.h"

#include <algorithm>
#include <utility>

#include "io/json/locate.h"

namespace rt {
namespace {

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

}  // namespace

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

}  // namespace rt
