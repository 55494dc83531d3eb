# Exports the open Blender scene as glTF 2.0 for rtcli, with what glTF alone cannot carry written
# into `extras` (Blender exports custom properties as extras):
#   - area lights: rtcli_area_light = {shape, size [x, y], color [r, g, b], power (W), two_sided}
#     on the light's object (glTF has no area lights; rtcli makes them rect lights);
#   - bump maps: rtcli_bump = {image, strength} on a material whose Principled BSDF normal comes
#     from a Bump node fed by an Image Texture (glTF has no height maps); the image is copied
#     beside the exported file.
# Settings: Y up (glTF's), cameras, punctual lights in physical units ("SPEC": W -> cd with
# 683 lm/W), extras, animation, modifiers applied. The custom properties are set for the export
# only: afterwards (even if the export fails) each is removed, or given back the value it had, so
# that they are not saved into the user's .blend.
#
# Usage (docs/scene-format.md, "From Blender"):
#   blender scene.blend --background --python tools/blender_export.py -- out.glb
# or from Blender's Scripting workspace: run this file with OUTPUT set below, or call
# export_for_rtcli("/path/out.glb") from the Python console after importing it.
#
# Licence: Apache-2.0, as the rest of rtcli.
import os
import shutil
import sys

import bpy

OUTPUT = None  # a path here is used when the script is run from Blender's text editor


def bump_source(material):
    """The (image node, Bump node) feeding the material's Principled BSDF normal, or None."""
    if not material.use_nodes:
        return None
    for node in material.node_tree.nodes:
        if node.type != 'BSDF_PRINCIPLED':
            continue
        normal = node.inputs.get('Normal')
        if not normal or not normal.is_linked:
            return None
        bump = normal.links[0].from_node
        if bump.type != 'BUMP':
            return None
        height = bump.inputs.get('Height')
        if not height or not height.is_linked:
            return None
        image = height.links[0].from_node
        if image.type != 'TEX_IMAGE' or image.image is None:
            return None
        return image, bump
    return None


def set_property(block, key, value, marked):
    """block[key] = value, remembering what was there (marked) so that restore() can undo it."""
    previous = block.get(key)
    if hasattr(previous, 'to_dict'):  # an IDPropertyGroup: copy it before it is replaced
        previous = previous.to_dict()
    marked.append((block, key, key in block, previous))
    block[key] = value


def restore(marked):
    """Undoes set_property, last first: each key removed, or given back its earlier value."""
    for block, key, existed, previous in reversed(marked):
        if existed:
            block[key] = previous
        elif key in block:
            del block[key]
    marked.clear()


def mark_area_lights(scene, marked):
    """rtcli_area_light extras on every area light's object."""
    count = 0
    for obj in scene.objects:
        if obj.type != 'LIGHT' or obj.data.type != 'AREA':
            continue
        light = obj.data
        square = light.shape in ('SQUARE', 'DISK')
        size_y = light.size if square else light.size_y
        set_property(obj, 'rtcli_area_light', {
            'shape': light.shape,
            'size': [light.size, size_y],
            'color': list(light.color),
            'power': light.energy,
            'two_sided': False,
        }, marked)
        count += 1
    return count


def mark_bump_maps(scene, out_dir, marked):
    """rtcli_bump extras on bump-mapped materials; their height images copied beside the export."""
    count = 0
    for material in bpy.data.materials:
        found = bump_source(material)
        if not found:
            continue
        image_node, bump = found
        source = bpy.path.abspath(image_node.image.filepath)
        name = os.path.basename(source) or (image_node.image.name + '.png')
        target = os.path.join(out_dir, name)
        if os.path.isfile(source):
            if os.path.abspath(source) != os.path.abspath(target):
                shutil.copyfile(source, target)
        else:  # packed or generated: save a copy
            image_node.image.save_render(target)
        # Blender's bump height is the texel value times Distance, scaled by Strength.
        strength = bump.inputs['Strength'].default_value * bump.inputs['Distance'].default_value
        set_property(material, 'rtcli_bump', {'image': name, 'strength': -strength if bump.invert else strength},
                     marked)
        count += 1
    return count


def export_for_rtcli(path):
    path = os.path.abspath(path)
    out_dir = os.path.dirname(path)
    os.makedirs(out_dir, exist_ok=True)
    scene = bpy.context.scene
    marked = []
    try:
        areas = mark_area_lights(scene, marked)
        bumps = mark_bump_maps(scene, out_dir, marked)
        bpy.ops.export_scene.gltf(
            filepath=path,
            export_format='GLB' if path.lower().endswith('.glb') else 'GLTF_SEPARATE',
            export_yup=True,
            export_cameras=True,
            export_lights=True,
            convert_lighting_mode='SPEC',
            export_extras=True,
            export_apply=True,
            export_animations=True,
        )
    finally:
        restore(marked)  # the user's objects and materials as they were
    print('rtcli: wrote %s (%d area lights, %d bump maps as extras)' % (path, areas, bumps))


if __name__ == '__main__':
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    target = argv[0] if argv else OUTPUT
    if not target:
        raise SystemExit('usage: blender scene.blend --background --python tools/blender_export.py -- out.glb')
    export_for_rtcli(target)
