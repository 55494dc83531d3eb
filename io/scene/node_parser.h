// The "nodes" tree of a scene file: names, transforms, shapes, mesh references, materials.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/json/reader.h"
#include "io/scene/description.h"

namespace rt {

// A node under "templates", not yet parsed: it is parsed the first time a node places it, in
// the folder of the file that defines it.
struct TemplateSource {
  const Json* value = nullptr;
  std::string pointer;
  std::string folder;
};

struct NodeParseContext {
  const JsonReader& reader;
  std::string scene_folder;  // mesh files resolve against it
  const std::vector<MaterialDescription>& materials;
  std::map<std::string, std::string> names{};  // node name -> pointer of its first use
  uint64_t max_nodes = 0;                      // LoadLimits::nodes
  uint64_t nodes = 0;                          // parsed so far
  // While the operands of a CSG node are parsed: how many CSG nodes enclose them, and whether one
  // of those gives a material (then a shape operand may go without its own).
  int csg_depth = 0;
  bool csg_material = false;
  // Templates by name (the last file's definition), those parsed so far (empty: it failed),
  // and those being parsed (to refuse a template that places itself).
  std::map<std::string, TemplateSource> templates{};
  std::map<std::string, std::optional<NodeDescription>> parsed_templates{};
  std::vector<std::string> template_stack{};
  int in_template = 0;  // > 0: parsing a template, whose shapes may take their material where placed
};

inline constexpr int kMaxNodeDepth = 128;  // deeper trees are refused rather than risking the stack

// depth: how many node levels enclose this array (0 for the top-level "nodes").
std::vector<NodeDescription> parse_nodes(NodeParseContext& ctx, const Json& value, const std::string& pointer,
                                         int depth = 0);

// One node and its subtree (a template's too: io/scene/template_placement.h), at `depth` levels.
NodeDescription parse_node(NodeParseContext& ctx, const Json& value, const std::string& pointer, int depth);

// The index of the material a name names under /materials; nothing, after an error at `pointer`
// listing the names (and the nearest), if none does.
std::optional<uint32_t> resolve_material(NodeParseContext& ctx, const Json& value, const std::string& pointer);

// A "transform" object: translate / rotate (degrees) / scale, or a 4x4 "matrix" (rows).
// Rotations are kept as quaternions (R = Rz * Ry * Rx of the Euler angles).
std::optional<NodeTransform> parse_transform(const JsonReader& r, const Json& value, const std::string& pointer);

}  // namespace rt
