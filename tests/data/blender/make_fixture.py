# Builds the Blender test fixture from Blender's factory scene and exports it with
# tools/blender_export.py, exactly as a user would export their own scene. CI does not run it;
# the files it writes are checked in (tests/io/gltf/test_blender_fixture.cpp loads them):
#
#   apt-get install blender python3-numpy
#   blender --background --factory-startup --python tests/data/blender/make_fixture.py -- tests/data/blender/fixture.glb
#
# The scene: a floor with a bump-mapped material ("Floor", height image "ridges.png"), a box
# ("Red") turning over frames 1-24, a ball ("Glass", transmission 1), a camera ("Camera"), a
# 2 x 1 m area light ("Softbox", 150 W), a sun ("Sun", 3 W/m^2) and a point light ("Lamp", 200 W).
import importlib.util
import math
import os
import sys

import bpy
from mathutils import Vector

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..', '..'))


def load_exporter():
    spec = importlib.util.spec_from_file_location('blender_export', os.path.join(REPO, 'tools', 'blender_export.py'))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def principled(name, colour, metallic=0.0, roughness=0.5):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes['Principled BSDF']
    bsdf.inputs['Base Color'].default_value = (*colour, 1.0)
    bsdf.inputs['Metallic'].default_value = metallic
    bsdf.inputs['Roughness'].default_value = roughness
    return m, bsdf


def ridges_image(path, size=32):
    """A height map of vertical ridges, saved as PNG."""
    image = bpy.data.images.new('ridges', size, size)
    pixels = []
    for y in range(size):
        for x in range(size):
            h = 0.5 + 0.5 * math.sin(2 * math.pi * x / 8)
            pixels += [h, h, h, 1.0]
    image.pixels = pixels
    image.filepath_raw = path
    image.file_format = 'PNG'
    image.save()
    return image


def look_at(obj, target):
    direction = Vector(target) - obj.location
    obj.rotation_mode = 'QUATERNION'
    obj.rotation_quaternion = direction.to_track_quat('-Z', 'Y')


def build(out_dir):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, 24

    bpy.ops.mesh.primitive_plane_add(size=10)
    floor = bpy.context.active_object
    floor.name = 'Floor'
    floor_material, bsdf = principled('Floor', (0.6, 0.58, 0.55), roughness=0.8)
    nodes, links = floor_material.node_tree.nodes, floor_material.node_tree.links
    height = nodes.new('ShaderNodeTexImage')
    height.image = ridges_image(os.path.join(out_dir, 'ridges.png'))
    height.image.colorspace_settings.name = 'Non-Color'
    bump = nodes.new('ShaderNodeBump')
    bump.inputs['Strength'].default_value = 0.5
    bump.inputs['Distance'].default_value = 0.4
    links.new(height.outputs['Color'], bump.inputs['Height'])
    links.new(bump.outputs['Normal'], bsdf.inputs['Normal'])
    floor.data.materials.append(floor_material)

    bpy.ops.mesh.primitive_cube_add(size=1, location=(-1.2, 0, 0.5))
    box = bpy.context.active_object
    box.name = 'Box'
    box.data.materials.append(principled('Red', (0.8, 0.1, 0.08), roughness=0.4)[0])
    box.rotation_euler = (0, 0, 0)
    box.keyframe_insert('rotation_euler', frame=1)
    box.rotation_euler = (0, 0, math.radians(90))
    box.keyframe_insert('rotation_euler', frame=24)

    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.7, location=(1.2, 0, 0.7))
    ball = bpy.context.active_object
    ball.name = 'Ball'
    bpy.ops.object.shade_smooth()
    glass, bsdf = principled('Glass', (1.0, 1.0, 1.0), roughness=0.0)
    bsdf.inputs['Transmission'].default_value = 1.0
    bsdf.inputs['IOR'].default_value = 1.45
    ball.data.materials.append(glass)

    bpy.ops.object.camera_add(location=(0, -7, 3.5))
    camera = bpy.context.active_object
    camera.name = 'Camera'
    camera.data.lens = 35
    look_at(camera, (0, 0, 0.5))
    scene.camera = camera

    bpy.ops.object.light_add(type='AREA', location=(0, 0, 4))
    softbox = bpy.context.active_object
    softbox.name = 'Softbox'
    softbox.data.shape = 'RECTANGLE'
    softbox.data.size, softbox.data.size_y = 2.0, 1.0
    softbox.data.energy = 150.0
    softbox.data.color = (1.0, 0.95, 0.9)

    bpy.ops.object.light_add(type='SUN', location=(0, 0, 6), rotation=(math.radians(40), 0, math.radians(30)))
    sun = bpy.context.active_object
    sun.name = 'Sun'
    sun.data.energy = 3.0

    bpy.ops.object.light_add(type='POINT', location=(3, -3, 3))
    lamp = bpy.context.active_object
    lamp.name = 'Lamp'
    lamp.data.energy = 200.0


if __name__ == '__main__':
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    out = os.path.abspath(argv[0] if argv else os.path.join(HERE, 'fixture.glb'))
    build(os.path.dirname(out))
    load_exporter().export_for_rtcli(out)
