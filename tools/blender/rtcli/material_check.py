# The material nodes rtcli cannot represent: what Blender's glTF exporter does not map (its
# Principled BSDF, Image Texture, Normal Map, Separate RGB/Color for metallic-roughness, Mapping
# and UV Map for KHR_texture_transform, Emission, Mix and Add Shader with Transparent or Emission,
# Vertex Color / Attribute, and rtcli's Bump extras) is dropped by the export, so each material's
# list is shown once, in a warning, instead of silently changing the picture.
#
# Licence: Apache-2.0, as the rest of rtcli.

# Node types the export carries (bpy.types.Node.type).
MAPPED = {
    'BSDF_PRINCIPLED', 'TEX_IMAGE', 'NORMAL_MAP', 'BUMP', 'SEPRGB', 'SEPARATE_COLOR', 'SEPXYZ', 'MAPPING',
    'UVMAP', 'TEX_COORD', 'EMISSION', 'MIX_SHADER', 'ADD_SHADER', 'BSDF_TRANSPARENT', 'VERTEX_COLOR',
    'ATTRIBUTE', 'OUTPUT_MATERIAL', 'REROUTE', 'GROUP_INPUT', 'GROUP_OUTPUT', 'VALUE', 'RGB',
    'SEPARATE_XYZ', 'MIX_RGB', 'MIX', 'MATH',
}
# Mix (a colour times a vertex colour or a factor) and Math (factors) are mapped in some
# arrangements only: listed unless they feed the Principled BSDF directly.
PARTLY = {'MIX_RGB', 'MIX', 'MATH'}

# Principled BSDF inputs the glTF exporter (3.4 to 4.x) does not write: listed when set or linked.
# (name, the value that means "off")
IGNORED_INPUTS = (
    ('Subsurface', 0.0), ('Subsurface Weight', 0.0), ('Sheen', 0.0), ('Sheen Tint', 0.5), ('Anisotropic', 0.0),
    ('Clearcoat Roughness', 0.03), ('Coat Roughness', 0.03),
)


def _upstream(node, seen):
    """Every node feeding `node`, through its linked inputs, each once."""
    for socket in node.inputs:
        for link in socket.links:
            source = link.from_node
            if source.name in seen:
                continue
            seen[source.name] = source
            _upstream(source, seen)
    return seen


def _output(tree):
    outputs = [n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL']
    active = [n for n in outputs if n.is_active_output and n.target in ('ALL', 'CYCLES')]
    return (active or outputs or [None])[0]


def _label(node):
    return node.bl_label if node.name == node.bl_label else '%s "%s"' % (node.bl_label, node.name)


def unrepresented(material):
    """What of `material` rtcli will not show: a list of short descriptions (empty: all of it)."""
    if material is None or not material.use_nodes or material.node_tree is None:
        return []
    output = _output(material.node_tree)
    if output is None:
        return []
    found = []
    principled_fed = set()
    used = _upstream(output, {}).values()
    for node in used:
        if node.type == 'BSDF_PRINCIPLED':
            principled_fed.update(link.from_node.name for s in node.inputs for link in s.links)
            for name, off in IGNORED_INPUTS:
                socket = node.inputs.get(name)
                if socket is None:
                    continue
                if socket.is_linked:
                    found.append('Principled BSDF input %s (linked)' % name)
                elif isinstance(socket.default_value, float) and abs(socket.default_value - off) > 1e-6:
                    found.append('Principled BSDF input %s (%.3g)' % (name, socket.default_value))
    for node in used:
        if node.type in MAPPED and not (node.type in PARTLY and node.name not in principled_fed):
            continue
        if node.type == 'GROUP':
            found.append('node group %s' % _label(node))
        else:
            found.append(_label(node))
    return sorted(set(found))


def warnings_for(materials):
    """One warning per material that loses something, naming what."""
    out = []
    for material in materials:
        lost = unrepresented(material)
        if lost:
            out.append('material "%s": rtcli cannot represent %s; the export drops %s' %
                       (material.name, ', '.join(lost), 'it' if len(lost) == 1 else 'them'))
    return out
