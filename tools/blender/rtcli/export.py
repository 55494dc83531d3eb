# Exports the open Blender scene as glTF 2.0 for rtcli, with what glTF alone cannot carry written
# into `extras` (Blender exports custom properties as extras). The one exporter: the render engine
# (tools/blender/rtcli) calls it for every render, tools/blender_export.py for a file by hand.
#   - area lights: rtcli_area_light = {shape, size [x, y], color [r, g, b], power (W), two_sided,
#     camera (Object > Visibility > Camera)} on the light's object (glTF has no area lights; rtcli
#     makes them rect lights);
#   - bump maps: rtcli_bump = {image, strength} on a material whose Principled BSDF normal comes
#     from a Bump node fed by an Image Texture (glTF has no height maps); the image is copied
#     beside the exported file;
#   - the world: rtcli_world = {color [r, g, b], strength} (a Background colour, or a world without
#     nodes) or {image, strength, rotation} (an Environment Texture, equirectangular; its image
#     beside the exported file as .hdr or .exr; rotation in rtcli's degrees about +Y: Blender's
#     image centre faces +X, rtcli's -Z, so 90 plus a Mapping node's Z rotation) on the scene.
# Settings: Y up (glTF's), cameras, punctual lights in physical units ("SPEC": W -> cd with
# 683 lm/W), extras, animation, modifiers applied. The custom properties are set for the export
# only: afterwards (even if the export fails) each is removed, or given back the value it had, so
# that they are not saved into the user's .blend.
# What the export cannot carry is returned as warnings (a world's unsupported nodes), for the
# caller to show: the render engine in Blender's report, the script on its console.
#
# Licence: Apache-2.0, as the rest of rtcli.
import math
import os
import shutil

import bpy


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
            'camera': bool(getattr(obj, 'visible_camera', True)),  # Cycles hides lights from the camera by default
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


def write_hdr(image, target):
    """A Blender image (packed, generated, or 8-bit) as a flat Radiance .hdr of its linear values."""
    import numpy  # Blender's Python has it; the tests' stand-in bpy does not need it
    width, height = image.size
    pixels = numpy.empty(width * height * 4, numpy.float32)
    image.pixels.foreach_get(pixels)
    rgb = pixels.reshape(height, width, 4)[::-1, :, :3].astype(numpy.float64)  # Blender's rows start at the bottom
    if not image.is_float and image.colorspace_settings.name in ('sRGB', 'Filmic sRGB'):
        rgb = numpy.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    rgb = numpy.maximum(rgb, 0.0)
    top = rgb.max(axis=2)
    mantissa, exponent = numpy.frexp(top)
    scale = numpy.where(top > 1e-32, mantissa * 256.0 / numpy.maximum(top, 1e-32), 0.0)
    rgbe = numpy.zeros((height, width, 4), numpy.uint8)
    rgbe[:, :, :3] = numpy.minimum(rgb * scale[:, :, None], 255).astype(numpy.uint8)
    rgbe[:, :, 3] = numpy.where(top > 1e-32, exponent + 128, 0).astype(numpy.uint8)
    with open(target, 'wb') as f:  # flat scanlines: no run-length encoding
        f.write(b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n' % (height, width))
        f.write(rgbe.tobytes())
    return target


def world_settings(scene, out_dir, warnings):
    """The rtcli_world value for the scene's world (its image copied into out_dir)."""
    world = scene.world
    if world is None:
        return {'color': [0.0, 0.0, 0.0], 'strength': 1.0}  # Cycles renders no world as black
    if not world.use_nodes:
        return {'color': list(world.color), 'strength': 1.0}
    tree = world.node_tree
    output = next((n for n in tree.nodes if n.type == 'OUTPUT_WORLD' and n.is_active_output), None)
    output = output or next((n for n in tree.nodes if n.type == 'OUTPUT_WORLD'), None)
    surface = output.inputs.get('Surface') if output else None
    if surface is None or not surface.is_linked:
        return {'color': [0.0, 0.0, 0.0], 'strength': 1.0}
    background = surface.links[0].from_node
    if background.type != 'BACKGROUND':
        warnings.append('world "%s": its %s node is not a Background node; rtcli uses the world\'s viewport '
                        'colour' % (world.name, background.bl_label))
        return {'color': list(world.color), 'strength': 1.0}
    strength = background.inputs['Strength'].default_value
    if background.inputs['Strength'].is_linked:
        warnings.append('world "%s": a linked Strength is read as 1' % world.name)
        strength = 1.0
    color = background.inputs['Color']
    if not color.is_linked:
        return {'color': list(color.default_value)[:3], 'strength': strength}
    texture = color.links[0].from_node
    if texture.type != 'TEX_ENVIRONMENT' or texture.image is None or texture.projection != 'EQUIRECTANGULAR':
        warnings.append('world "%s": its Background colour comes from a %s node, which rtcli cannot represent '
                        '(an equirectangular Environment Texture with an image can); rtcli uses the world\'s '
                        'viewport colour' % (world.name, texture.bl_label))
        return {'color': list(world.color), 'strength': strength}
    rotation = 0.0
    vector = texture.inputs.get('Vector')
    if vector is not None and vector.is_linked:
        mapping = vector.links[0].from_node
        if mapping.type == 'MAPPING' and mapping.inputs.get('Rotation') is not None:
            rotation = math.degrees(mapping.inputs['Rotation'].default_value[2])
            if any(abs(v) > 1e-6 for v in mapping.inputs['Rotation'].default_value[:2]):
                warnings.append('world "%s": only the Mapping node\'s Z rotation is carried over' % world.name)
        else:
            warnings.append('world "%s": the environment\'s %s vector is ignored' % (world.name, mapping.bl_label))
    image = texture.image
    source = bpy.path.abspath(image.filepath) if image.filepath else ''
    extension = os.path.splitext(source)[1].lower()
    if os.path.isfile(source) and extension in ('.hdr', '.exr') and not image.packed_file:
        name = 'world' + extension
        shutil.copyfile(source, os.path.join(out_dir, name))
    else:  # packed, generated, or an 8-bit format rtcli's environments do not read
        name = 'world.hdr'
        write_hdr(image, os.path.join(out_dir, name))
    # Into rtcli's convention, wrapped into its range (-360, 360).
    turn = math.fmod(90.0 + rotation, 360.0)
    return {'image': name, 'strength': strength, 'rotation': turn}


def mark_world(scene, out_dir, marked, warnings):
    set_property(scene, 'rtcli_world', world_settings(scene, out_dir, warnings), marked)


def export_for_rtcli(path, animations=True):
    """Writes the scene to `path` (.glb or .gltf); returns the warnings on what does not carry over."""
    path = os.path.abspath(path)
    out_dir = os.path.dirname(path)
    os.makedirs(out_dir, exist_ok=True)
    scene = bpy.context.scene
    marked = []
    warnings = []
    try:
        areas = mark_area_lights(scene, marked)
        bumps = mark_bump_maps(scene, out_dir, marked)
        mark_world(scene, out_dir, marked, warnings)
        bpy.ops.export_scene.gltf(
            filepath=path,
            export_format='GLB' if path.lower().endswith('.glb') else 'GLTF_SEPARATE',
            export_yup=True,
            export_cameras=True,
            export_lights=True,
            convert_lighting_mode='SPEC',
            export_extras=True,
            export_apply=True,
            export_animations=animations,
        )
    finally:
        restore(marked)  # the user's objects, materials and scene as they were
    print('rtcli: wrote %s (%d area lights, %d bump maps as extras)' % (path, areas, bumps))
    return warnings
