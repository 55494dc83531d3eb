// Templates: named nodes under "templates" (any file of a scene), placed by a node's
// "template": NAME. A template is parsed the first time it is placed (in its own file's folder,
// with names of its own; its shapes may leave their material to the placement) and copied at
// each placement: the placing node becomes a group holding the copy, with the placement's
// "material" for the template's shapes and CSG nodes that have none, its "materials" swaps, and
// the names inside prefixed with its own. The geometry is not copied: a glTF mesh is loaded once
// however often it is placed, a shape is a few numbers. A template that places itself, a copy
// past the node or nesting limits, a shape left without a material are errors at the placement.
#pragma once

#include "io/scene/node_parser.h"

namespace rt {

// `node` is the placing node, parsed but for its template (`name_value`, with `swaps_value` its
// "materials"); `o` reads it. `depth`: the levels above it.
void place_template(NodeParseContext& ctx, ObjectReader& o, NodeDescription& node, const Json& name_value,
                    const Json* swaps_value, int depth);

}  // namespace rt
