"""The Blender fixture (tests/data/blender/make_fixture.py) rendered by Cycles, after the fixture
script has built and exported it in the same Blender session:

  blender -b --factory-startup --python-exit-code 1 --python tests/data/blender/make_fixture.py \
      --python tools/cycles/fixture.py -- OUT.glb [SAMPLES] [WIDTH] [HEIGHT] [ONLY_LIGHT|all] [FLOOR|-]
      [EXPOSURE] [VIEW]

writes OUT.glb (the export, for rtcli) and OUT.cycles.png: frame 1, the world the grey rtcli gives
a model without one (0.0509, Blender's default world), CPU, a box filter one pixel wide, no
denoiser or clamping, 10 bounces, Russian roulette from the fourth (min_light_bounces 3, as rtcli),
the Standard view transform. With ONLY_LIGHT (Softbox, Sun or
Lamp) every other light is switched off and the scene exported again, so that each light's units
can be compared alone. FLOOR changes the floor for Cycles only, after the export, so that rtcli's
input stays the same: "no-bump" unlinks its bump node, "diffuse" makes it a Diffuse BSDF of the
same colour (Lambert, no bump), to measure what each part of the material contributes.
EXPOSURE (stops, default 0; rtcli's --exposure) keeps a bright floor from clipping in the PNG.
VIEW is the view transform (default Standard; Filmic for rtcli's --view-transform Filmic).
"""
import importlib.util
import os
import sys
import time

import bpy

argv = sys.argv[sys.argv.index("--") + 1:]
out = os.path.abspath(argv[0])
samples = int(argv[1]) if len(argv) > 1 else 256
width = int(argv[2]) if len(argv) > 2 else 320
height = int(argv[3]) if len(argv) > 3 else 180
only = argv[4] if len(argv) > 4 and argv[4] != "all" else None
floor_variant = argv[5] if len(argv) > 5 and argv[5] != "-" else None
exposure = float(argv[6]) if len(argv) > 6 else 0.0
view = argv[7] if len(argv) > 7 else "Standard"
if only:
    for obj in bpy.data.objects:
        if obj.type == "LIGHT" and obj.name != only:
            obj.data.energy = 0.0
            obj.hide_render = True
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    spec = importlib.util.spec_from_file_location("blender_export", os.path.join(repo, "tools", "blender_export.py"))
    exporter = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(exporter)
    exporter.export_for_rtcli(out)

if floor_variant:
    tree = bpy.data.materials["Floor"].node_tree
    bsdf = tree.nodes["Principled BSDF"]
    for link in list(bsdf.inputs["Normal"].links):
        tree.links.remove(link)
    if floor_variant == "diffuse":
        diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = bsdf.inputs["Base Color"].default_value
        output = tree.nodes["Material Output"]
        tree.links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])
    elif floor_variant != "no-bump":
        sys.exit("fixture.py: FLOOR is no-bump or diffuse, not " + floor_variant)

s = bpy.context.scene
s.frame_set(1)
s.render.engine = "CYCLES"
s.cycles.device = "CPU"
s.cycles.samples = samples
s.cycles.use_adaptive_sampling = False
s.cycles.use_denoising = False
s.cycles.max_bounces = 10
s.cycles.min_light_bounces = 3  # Russian roulette from the fourth bounce, as rtcli's path tracer
for k in ("diffuse_bounces", "glossy_bounces", "transmission_bounces", "transparent_max_bounces"):
    setattr(s.cycles, k, 10)
s.cycles.sample_clamp_direct = 0.0
s.cycles.sample_clamp_indirect = 0.0
s.cycles.pixel_filter_type = "BOX"
s.cycles.filter_width = 1.0
s.render.threads_mode = "FIXED"
s.render.threads = 2
s.render.resolution_x, s.render.resolution_y, s.render.resolution_percentage = width, height, 100
s.view_settings.view_transform = view
s.view_settings.look = "None"
s.view_settings.exposure = exposure
world = bpy.data.worlds.new("world")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.0509, 0.0509, 0.0509, 1)
s.world = world
s.render.image_settings.file_format = "PNG"
s.render.filepath = os.path.splitext(out)[0] + ".cycles.png"
start = time.time()
bpy.ops.render.render(write_still=True)
print("cycles: rendered %s at %dx%d, %d samples, in %.4f s" % (s.render.filepath, width, height, samples,
                                                              time.time() - start))
