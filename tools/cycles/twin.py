"""Renders an rtcli scene file's twin with Blender's Cycles, for the path tracer's comparisons.

  blender -b --factory-startup --python-exit-code 1 -P tools/cycles/twin.py -- SCENE.json OUT.png \
      [--samples N] [--width W --height H] [--threads T]

Only what the twin needs for scenes like scenes/cornell_box.json and scenes/environment.json:
planes, cubes and spheres (a smooth UV sphere of 64 x 32 faces: Cycles traces triangles), rect
lights (a quad with an Emission shader of strength 1 and the light's colour: radiance, as rtcli's
rect lights), a perspective camera, the background as the world colour or an equirectangular
environment (strength = intensity; rtcli's image centre faces -Z, Blender's +X: a Mapping node
turns it by rotate - 90 degrees about Blender's Z). Materials: kd alone is a Diffuse BSDF (Lambert);
transmission a Glass BSDF of the ior (sharp); reflectivity R a Glossy BSDF of colour R, mixed over
the diffuse by R where kd is not 0, its roughness rtcli's `glossy` (the blur-square width: a
likeness, not the same lobe). Anything else is refused. rtcli is Y-up and Blender Z-up: a point (x, y, z) goes to
(x, -z, y), a proper rotation. Cycles runs on the CPU with a box pixel filter one pixel wide (as
rtcli's path sampler), no denoiser, no clamping, max bounces = render.max_depth, Russian roulette from
the fourth bounce (min_light_bounces 3, rtcli's start; both by Cycles' rule), the Standard view
transform (linear to sRGB, as rtcli's clamp tone map). Prints the render time Cycles reports.
"""
import json
import math
import os
import sys
import time

import bpy
from mathutils import Matrix, Vector

SHAPES = {
    # The shapes' canonical vertices and faces (rtcli: plane x, z in [-1, 1] at y = 0; cube [-1, 1]^3).
    "plane": ([(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)], [(0, 3, 2, 1)]),
    "cube": ([(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)],
             [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]),
}


def uv_sphere(segments=64, rings=32):
    """The unit sphere as quads (triangles at the poles), wound outwards."""
    verts = [(0, 1, 0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        verts += [(math.sin(theta) * math.sin(2 * math.pi * s / segments), math.cos(theta),
                   math.sin(theta) * math.cos(2 * math.pi * s / segments)) for s in range(segments)]
    verts.append((0, -1, 0))
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments
    faces = [(0, ring(1, s), ring(1, s + 1)) for s in range(segments)]
    for r in range(1, rings - 1):
        faces += [(ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s + 1)) for s in range(segments)]
    faces += [(len(verts) - 1, ring(rings - 1, s + 1), ring(rings - 1, s)) for s in range(segments)]
    return verts, faces


SHAPES["sphere"] = uv_sphere()


def to_blender(p):
    return Vector((p[0], -p[2], p[1]))


def colour(v, default):
    if v is None:
        return default
    return [float(v)] * 3 if isinstance(v, (int, float)) else [float(c) for c in v]


def trs(t):
    """rtcli's compose_trs: translate, then rotate z, y, x (degrees), then scale."""
    t = t or {}
    m = Matrix.Translation(Vector(t.get("translate", (0, 0, 0))))
    r = t.get("rotate", (0, 0, 0))
    for axis, angle in (("Z", r[2]), ("Y", r[1]), ("X", r[0])):
        m = m @ Matrix.Rotation(math.radians(angle), 4, axis)
    s = t.get("scale", 1)
    s = (s, s, s) if isinstance(s, (int, float)) else s
    return m @ Matrix.Diagonal(Vector((s[0], s[1], s[2], 1)))


def material(name, spec=None, emission=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if emission is not None:
        e = nodes.new("ShaderNodeEmission")
        e.inputs["Color"].default_value = (*emission, 1)
        e.inputs["Strength"].default_value = 1.0
        links.new(e.outputs["Emission"], out.inputs["Surface"])
        return m
    known = {"kd", "reflectivity", "glossy", "transmission", "ior"}
    if set(spec) - known:
        raise SystemExit("tools/cycles/twin.py: material %r: %s have no twin" % (name, sorted(set(spec) - known)))
    kd = colour(spec.get("kd"), [0.8] * 3)
    transmission = colour(spec.get("transmission"), [0, 0, 0])
    reflectivity = colour(spec.get("reflectivity"), [0, 0, 0])
    if max(transmission) > 0:
        g = nodes.new("ShaderNodeBsdfGlass")
        g.distribution = "SHARP"
        g.inputs["Color"].default_value = (*transmission, 1)
        g.inputs["IOR"].default_value = float(spec.get("ior", 1.5))
        links.new(g.outputs["BSDF"], out.inputs["Surface"])
        return m
    d = nodes.new("ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = (*kd, 1)
    d.inputs["Roughness"].default_value = 0.0  # Lambert
    if max(reflectivity) <= 0:
        links.new(d.outputs["BSDF"], out.inputs["Surface"])
        return m
    g = nodes.new("ShaderNodeBsdfGlossy")
    g.distribution = "GGX" if spec.get("glossy", 0) > 0 else "SHARP"
    g.inputs["Roughness"].default_value = float(spec.get("glossy", 0))
    if max(kd) <= 0:
        g.inputs["Color"].default_value = (*reflectivity, 1)
        links.new(g.outputs["BSDF"], out.inputs["Surface"])
        return m
    mix = nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = max(reflectivity)
    links.new(d.outputs["BSDF"], mix.inputs[1])
    links.new(g.outputs["BSDF"], mix.inputs[2])
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return m


def add_mesh(name, verts, faces, mat, smooth=False):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(v) for v in verts], [], faces)
    for polygon in mesh.polygons:
        polygon.use_smooth = smooth
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.data.materials.append(mat)
    bpy.context.scene.collection.objects.link(obj)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    scene_path, out = argv[0], argv[1]
    opts = dict(zip(argv[2::2], argv[3::2]))
    with open(scene_path) as f:
        scene = json.load(f)
    render = scene.get("render", {})

    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    s = bpy.context.scene
    s.render.engine = "CYCLES"
    s.cycles.device = "CPU"
    s.cycles.samples = int(opts.get("--samples", render.get("samples_per_pixel", 64)))
    s.cycles.use_adaptive_sampling = False
    s.cycles.use_denoising = False
    s.cycles.max_bounces = int(render.get("max_depth", 5))
    for k in ("diffuse_bounces", "glossy_bounces", "transmission_bounces", "transparent_max_bounces"):
        setattr(s.cycles, k, s.cycles.max_bounces)
    s.cycles.min_light_bounces = 3  # Russian roulette from the fourth bounce, as rtcli's path tracer
    s.cycles.sample_clamp_direct = 0.0
    s.cycles.sample_clamp_indirect = 0.0
    s.cycles.pixel_filter_type = "BOX"
    s.cycles.filter_width = 1.0
    s.cycles.seed = int(render.get("seed", 0))
    s.render.threads_mode = "FIXED"
    s.render.threads = int(opts.get("--threads", 2))
    s.render.resolution_x = int(opts.get("--width", render.get("width", 640)))
    s.render.resolution_y = int(opts.get("--height", render.get("height", 480)))
    s.render.resolution_percentage = 100
    s.view_settings.view_transform = "Standard"
    s.view_settings.look = "None"
    s.view_settings.exposure = float(render.get("exposure", 0))
    s.render.image_settings.file_format = "PNG"
    s.render.filepath = out

    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    sky = scene.get("background")
    if isinstance(sky, dict):
        nodes, links = world.node_tree.nodes, world.node_tree.links
        image = nodes.new("ShaderNodeTexEnvironment")
        folder = os.path.dirname(os.path.abspath(scene_path))
        image.image = bpy.data.images.load(os.path.join(folder, sky["environment"]))
        mapping, coords = nodes.new("ShaderNodeMapping"), nodes.new("ShaderNodeTexCoord")
        mapping.inputs["Rotation"].default_value[2] = math.radians(float(sky.get("rotate", 0)) - 90.0)
        links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
        links.new(mapping.outputs["Vector"], image.inputs["Vector"])
        links.new(image.outputs["Color"], background.inputs["Color"])
        background.inputs["Strength"].default_value = float(sky.get("intensity", 1))
    else:
        background.inputs["Color"].default_value = (*colour(sky, [0, 0, 0]), 1)
        background.inputs["Strength"].default_value = 1.0
    s.world = world

    mats = {n: material(n, m) for n, m in scene.get("materials", {}).items()}
    for node in scene.get("nodes", []):
        if node.get("shape") not in SHAPES:
            raise SystemExit("tools/cycles/twin.py: node %r has no twin (planes, cubes and spheres only)" %
                             node.get("name", "?"))
        verts, faces = SHAPES[node["shape"]]
        m = trs(node.get("transform"))
        add_mesh(node.get("name", node["shape"]), [to_blender(m @ Vector(v)) for v in verts], faces,
                 mats[node["material"]], smooth=node["shape"] == "sphere")
    for i, light in enumerate(scene.get("lights", [])):
        if light["type"] != "rect":
            raise SystemExit("tools/cycles/twin.py: only rect lights are twinned, found " + light["type"])
        c, e1, e2 = Vector(light["corner"]), Vector(light["edge1"]), Vector(light["edge2"])
        rgb = [x * float(light.get("intensity", 1)) for x in colour(light.get("color"), [1, 1, 1])]
        # Wound so that its front (edge1 x edge2 in rtcli) is Blender's face normal.
        add_mesh("light%d" % i, [to_blender(p) for p in (c, c + e1, c + e1 + e2, c + e2)], [(0, 1, 2, 3)],
                 material("light%d" % i, emission=rgb))

    cam = scene["camera"]
    pos, at = Vector(cam["position"]), Vector(cam.get("look_at", (0, 0, 0)))
    up = Vector(cam.get("up", (0, 1, 0)))
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle = math.radians(cam.get("fov", 60))
    obj = bpy.data.objects.new("camera", data)
    s.collection.objects.link(obj)
    forward, up_b = (to_blender(at) - to_blender(pos)).normalized(), to_blender(up)
    obj.matrix_world = Matrix.Translation(to_blender(pos)) @ forward.to_track_quat("-Z", "Y").to_matrix().to_4x4()
    # to_track_quat keeps Y as up only approximately: rebuild the frame from forward and up.
    right = forward.cross(up_b).normalized()
    true_up = right.cross(forward)
    frame = Matrix((right, true_up, -forward)).transposed().to_4x4()
    obj.matrix_world = Matrix.Translation(to_blender(pos)) @ frame
    s.camera = obj

    start = time.time()
    bpy.ops.render.render(write_still=True)
    print("cycles: rendered %s at %dx%d, %d samples, in %.4f s" % (out, s.render.resolution_x, s.render.resolution_y,
                                                                  s.cycles.samples, time.time() - start))


main()
