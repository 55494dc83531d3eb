#!/usr/bin/env python3
# Writes the "toys left behind" scenes (scenes/toys/): the proposal's final scene, every objective
# in one picture, in metres. toys.json is the still (a low camera with depth of field); the
# stereo anaglyph and the 360-degree panorama are the same room through other cameras
# (panorama.json), and turntable.json spins the toys on a round table. Run from the repository root.
import copy
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_json import T, write_scene  # noqa: E402

TEX = "../textures/"

materials = {
    "table": {"texture": {"file": TEX + "wood.png", "scale": [5, 5]}, "ks": 0.25, "shininess": 60, "reflectivity": 0.06},
    "wall": {"texture": {"file": TEX + "wallpaper.png", "scale": [8, 2.4]}, "ks": 0.02},
    "floor": {"kd": [0.35, 0.3, 0.26]},
    "ceiling": {"kd": 0.8},
    "box wood": {"texture": {"file": TEX + "wood.png", "scale": [1, 1]}, "kd": [1.0, 0.85, 0.7], "ks": 0.15, "shininess": 30},
    "box inside": {"texture": {"file": TEX + "wood.png", "scale": [2, 2]}, "kd": [0.6, 0.45, 0.35], "ks": 0.05},
    "brass": {"kd": [0.3, 0.22, 0.08], "ks": [0.8, 0.65, 0.3], "shininess": 120, "reflectivity": [0.6, 0.48, 0.22], "glossy": 0.05},
    "ivory": {"kd": [0.92, 0.9, 0.84], "ks": 0.35, "shininess": 80,
              "bump": {"file": TEX + "grain.png", "strength": 0.00012, "scale": [1, 1]}},
    "pip": {"kd": [0.04, 0.04, 0.05], "ks": 0.2, "shininess": 40},
    "red die": {"kd": [0.75, 0.08, 0.06], "ks": 0.4, "shininess": 90,
                "bump": {"file": TEX + "grain.png", "strength": 0.00012, "scale": [1, 1]}},
    "white pip": {"kd": 0.9, "ks": 0.2, "shininess": 40},
    "clear glass": {"kd": 0, "ks": 0.7, "shininess": 500, "transmission": 1, "ior": 1.5},
    "blue glass": {"kd": 0, "ks": 0.7, "shininess": 500, "transmission": 1, "ior": 1.52, "absorption": [40, 14, 2]},
    "green glass": {"kd": 0, "ks": 0.7, "shininess": 500, "transmission": 1, "ior": 1.55, "absorption": [30, 3, 25]},
    "amber glass": {"kd": 0, "ks": 0.7, "shininess": 500, "transmission": [1, 0.75, 0.35], "ior": 1.6},
    "crystal": {"kd": 0, "ks": 0.8, "shininess": 800, "transmission": 1, "ior": 2.0},
    "air": {"kd": 0, "ks": 0.5, "shininess": 500, "transmission": 1, "ior": 1.0},
    "rubber red": {"kd": [0.7, 0.06, 0.05], "ks": 0.5, "shininess": 40, "reflectivity": 0.08, "glossy": 0.25},
    "rubber blue": {"kd": [0.08, 0.2, 0.7], "ks": 0.5, "shininess": 40, "reflectivity": 0.08, "glossy": 0.25},
    "chrome": {"kd": 0.03, "ks": 0.9, "shininess": 600, "reflectivity": 0.9},
    "steel": {"kd": 0.15, "ks": 0.8, "shininess": 200, "reflectivity": 0.6, "glossy": 0.08},
    "card": {"texture": {"file": TEX + "card.png", "wrap": "clamp"}, "ks": 0.25, "shininess": 120},
    "card back": {"texture": {"file": TEX + "card_back.png", "wrap": "clamp"}, "ks": 0.25, "shininess": 120},
    "block red": {"kd": [0.72, 0.1, 0.08], "ks": 0.1, "shininess": 20},
    "block yellow": {"kd": [0.9, 0.7, 0.1], "ks": 0.5, "shininess": 80},
    "block blue": {"kd": [0.1, 0.22, 0.65], "ks": 0.5, "shininess": 80, "reflectivity": 0.12},
    "block green": {"kd": [0.12, 0.5, 0.2], "ks": 0.1, "shininess": 20},
    "block mirror": {"kd": 0.05, "ks": 0.8, "shininess": 300, "reflectivity": 0.75},
}


def die(name, centre, rotate, half, body, pip):
    """A die: a cube rounded by a sphere, minus its pips (opposite faces add up to 7)."""
    faces = {(1, 1): [(-1, -1), (1, 1), (0, 0), (-1, 1), (1, -1)], (1, -1): [(-1, -1), (1, 1)],
             (2, 1): [(0, 0)], (2, -1): [(-1, -1), (-1, 0), (-1, 1), (1, -1), (1, 0), (1, 1)],
             (0, 1): [(-1, -1), (0, 0), (1, 1)], (0, -1): [(-1, -1), (-1, 1), (1, -1), (1, 1)]}
    pips = []
    for (axis, sign), offsets in faces.items():
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for a, b in offsets:
            p = [0.0, 0.0, 0.0]
            p[axis] = sign * half * 1.02
            p[u] = 0.48 * half * a
            p[v] = 0.48 * half * b
            pips.append({"shape": "sphere", "material": pip, "transform": T(t=[round(x, 5) for x in p], s=0.19 * half)})
    return {"name": name, "csg": "difference", "transform": T(t=centre, r=rotate),
            "children": [{"csg": "intersection", "material": body,
                          "children": [{"shape": "cube", "transform": T(s=half)},
                                       {"shape": "sphere", "transform": T(s=half * 1.42)}]}] + pips}


def marble(name, centre, radius, material, bubble=None):
    if bubble is None:
        return {"name": name, "shape": "sphere", "material": material, "transform": T(t=centre, s=radius)}
    # A marble with an air bubble: the glass minus a small sphere inside it.
    return {"name": name, "csg": "difference", "material": material, "transform": T(t=centre),
            "children": [{"shape": "sphere", "transform": T(s=radius)},
                         {"shape": "sphere", "material": "air", "transform": T(t=bubble, s=0.28 * radius)}]}


def jack(name, centre, rotate, size, material):
    """Six arms: three crossed cylinders, sphere knobs on four ends and cones on two."""
    r = 0.08 * size
    arms = [{"shape": "cylinder", "material": material, "transform": T(t=t, r=rr, s=[r, r, 2 * size])}
            for t, rr in [([0, 0, -size], [0, 0, 0]), ([-size, 0, 0], [0, 90, 0]), ([0, -size, 0], [-90, 0, 0])]]
    knobs = [{"shape": "sphere", "material": material, "transform": T(t=t, s=0.2 * size)}
             for t in [[size, 0, 0], [-size, 0, 0], [0, 0, size], [0, 0, -size]]]
    tips = [{"shape": "cone", "material": material, "transform": T(t=[0, y, 0], r=[rx, 0, 0], s=[0.18 * size, 0.18 * size, 0.3 * size])}
            for y, rx in [(size * 1.3, 90), (-size * 1.3, -90)]]
    return {"name": name, "transform": T(t=centre, r=rotate), "children": arms + knobs + tips}


def card(name, centre, rotate, face_up=True):
    w, d, t = 0.032, 0.045, 0.0004
    return {"name": name, "transform": T(t=centre, r=rotate), "children": [
        {"shape": "cube", "material": "card back", "transform": T(s=[w, t, d])},
        # The face: a plane just above the top, its texture the right way up from the camera.
        {"shape": "plane", "material": "card" if face_up else "card back",
         "transform": T(t=[0, t * 1.05, 0], s=[w, 1, d])}]}


def toy_box(centre, rotate):
    w, h, d, wall = 0.22, 0.14, 0.15, 0.012
    posts = [{"shape": "cylinder", "material": "box wood",
              "transform": T(t=[x * (w + 0.004), -0.005, z * (d + 0.004)], r=[-90, 0, 0], s=[0.016, 0.016, 2 * h + 0.03])}
             for x in (-1, 1) for z in (-1, 1)]
    knobs = [{"shape": "sphere", "material": "brass", "transform": T(t=[x * (w + 0.004), 2 * h + 0.03, z * (d + 0.004)], s=0.02)}
             for x in (-1, 1) for z in (-1, 1)]
    body = {"name": "box body", "csg": "difference", "transform": T(t=[0, h, 0]), "children": [
        {"shape": "cube", "material": "box wood", "transform": T(s=[w, h, d])},
        {"shape": "cube", "material": "box inside", "transform": T(t=[0, wall + 0.02, 0], s=[w - wall, h, d - wall])}]}
    # The lid, hinged along the back edge and propped open.
    lid = {"name": "lid hinge", "transform": T(t=[0, 2 * h, -d], r=[-35, 0, 0]), "children": [
        {"name": "lid", "shape": "cube", "material": "box wood", "transform": T(t=[0, 0.008, d], s=[w + 0.01, 0.008, d + 0.01])},
        {"name": "hinge rod", "shape": "cylinder", "material": "brass", "transform": T(t=[-w, 0, 0], r=[0, 90, 0], s=[0.006, 0.006, 2 * w])}]}
    return {"name": "toy box", "transform": T(t=centre, r=rotate), "children": [body, lid] + posts + knobs}


def blocks():
    return [
        {"name": "block 1", "shape": "cube", "material": "block red", "transform": T(t=[0.26, 0.025, -0.14], r=[0, 20, 0], s=0.025)},
        {"name": "block 2", "shape": "cube", "material": "block yellow", "transform": T(t=[0.265, 0.075, -0.14], r=[0, 35, 0], s=0.025)},
        {"name": "block cone", "shape": "cone", "material": "block green", "transform": T(t=[0.265, 0.15, -0.14], r=[90, 0, 0], s=[0.026, 0.026, 0.05])},
        {"name": "block pillar", "shape": "cylinder", "material": "block blue", "transform": T(t=[0.17, 0, -0.24], r=[-90, 0, 0], s=[0.02, 0.02, 0.09])},
        {"name": "block mirror", "shape": "cube", "material": "block mirror", "transform": T(t=[0.3, 0.022, 0.02], r=[0, -25, 0], s=0.022)},
        {"name": "block arch", "csg": "difference", "material": "block yellow", "transform": T(t=[0.05, 0.03, -0.16], r=[0, 20, 0]),
         "children": [{"shape": "cube", "transform": T(s=[0.05, 0.03, 0.018])},
                      {"shape": "cylinder", "transform": T(t=[0, -0.03, -0.03], s=[0.03, 0.03, 0.06])}]},
    ]


def toys():
    return [
        toy_box([-0.24, 0, -0.36], [0, 48, 0]),
        die("die 1", [0.02, 0.02, 0.12], [0, 28, 0], 0.02, "ivory", "pip"),
        die("die 2", [0.075, 0.02, 0.07], [0, -14, 90], 0.02, "red die", "white pip"),
        marble("marble clear", [-0.08, 0.016, 0.2], 0.016, "clear glass", bubble=[0.004, 0.003, 0.0]),
        marble("marble blue", [-0.04, 0.016, 0.28], 0.016, "blue glass"),
        marble("marble green", [0.12, 0.016, 0.2], 0.016, "green glass"),
        marble("marble amber", [-0.13, 0.016, 0.1], 0.016, "amber glass"),
        marble("marble crystal", [0.19, 0.014, 0.22], 0.014, "crystal"),
        {"name": "rubber ball", "shape": "sphere", "material": "rubber red", "transform": T(t=[0.2, 0.06, -0.02], s=0.06)},
        {"name": "bouncy ball", "shape": "sphere", "material": "rubber blue", "transform": T(t=[-0.36, 0.03, 0.05], s=0.03)},
        {"name": "chrome ball", "shape": "sphere", "material": "chrome", "transform": T(t=[-0.2, 0.035, 0.12], s=0.035)},
        jack("jack 1", [-0.03, 0.011, 0.24], [20, 30, 35], 0.022, "steel"),
        jack("jack 2", [0.1, 0.011, 0.25], [-15, 70, 30], 0.022, "steel"),
        card("card 1", [-0.17, 0.0005, 0.22], [0, -25, 0]),
        card("card 2", [-0.13, 0.0012, 0.26], [0, 12, 0], face_up=False),
    ] + blocks()


def room():
    return [
        {"name": "table", "shape": "plane", "material": "table", "transform": T(s=[1.2, 1, 0.8])},
        {"name": "floor", "shape": "plane", "material": "floor", "transform": T(t=[0, -0.75, 0], s=4)},
        {"name": "ceiling", "shape": "plane", "material": "ceiling", "transform": T(t=[0, 1.6, 0], r=[180, 0, 0], s=4)},
        {"name": "back wall", "shape": "plane", "material": "wall", "transform": T(t=[0, 0.4, -0.8], r=[90, 0, 0], s=[4, 1, 1.2])},
        {"name": "front wall", "shape": "plane", "material": "wall", "transform": T(t=[0, 0.4, 2.5], r=[-90, 0, 0], s=[4, 1, 1.2])},
        {"name": "left wall", "shape": "plane", "material": "wall", "transform": T(t=[-2, 0.4, 0], r=[90, 90, 0], s=[4, 1, 1.2])},
        {"name": "right wall", "shape": "plane", "material": "wall", "transform": T(t=[2, 0.4, 0], r=[90, -90, 0], s=[4, 1, 1.2])},
    ]


lights = [
    {"type": "rect", "corner": [-0.75, 1.0, -0.55], "edge1": [0.45, 0, 0], "edge2": [0, 0, 0.45], "color": [1, 0.93, 0.82], "intensity": 1.25},
    {"type": "point", "position": [0.8, 0.6, 1.6], "color": [0.25, 0.28, 0.35]},
]

render = {"width": 1280, "height": 720, "max_depth": 8, "seed": 1, "shadow_samples": 8, "glossy_samples": 6,
          "antialias": {"mode": "adaptive", "threshold": 0.06, "max_depth": 3}}

still = {
    "$schema": "../../schemas/scene.schema.json",
    "render": render,
    "camera": {"position": [0.1, 0.17, 0.64], "look_at": [-0.05, 0.08, -0.06], "fov": 40,
               "aperture": 0.0025, "focus_distance": 0.56},
    "background": [0.05, 0.05, 0.06], "ambient": 0.05,
    "materials": materials, "lights": lights, "nodes": room() + toys(),
}
write_scene("scenes/toys/toys.json", still)

panorama = copy.deepcopy(still)
panorama["render"] = dict(render, width=2048, height=1024)
panorama["camera"] = {"position": [-0.05, 0.1, 0.0], "look_at": [-0.25, 0.1, -0.4], "projection": "equirectangular",
                      "stereo": {"mode": "top_bottom", "convergence": 0.4, "eye_separation": 0.02}}
write_scene("scenes/toys/panorama.json", panorama)

# The turntable: the toys on a round tray, turned 3 degrees a frame for 120 frames (a 4-second loop
# at 30 fps); the lights stay put, so the shadows do too.
spin = copy.deepcopy(still)
spin["render"] = dict(render, width=320, height=180, antialias={"mode": "adaptive", "threshold": 0.1, "max_depth": 2})
spin["camera"] = {"position": [0.0, 0.36, 0.95], "look_at": [0, 0.04, 0], "fov": 36}
# The tray's top stands 1 mm above the table: a top in the table's plane met the table at exactly
# the same distance, and which surface won such a tie followed the BVH's traversal order (a few
# frames showed the table's grain through the tray).
tray = {"name": "turntable", "children": [
    {"name": "tray", "shape": "cylinder", "material": "box inside", "transform": T(t=[0, -0.009, 0], r=[-90, 0, 0], s=[0.55, 0.55, 0.01])},
    # Everything but the toy box, which would hide the rest for a third of the turn.
    {"name": "toys", "transform": T(t=[-0.05, 0, -0.05]), "children": toys()[1:]}]}
spin["nodes"] = room() + [tray]
spin["animation"] = {"fps": 30, "frames": [0, 119], "tracks": [{"node": "turntable", "property": "rotate", "keys": [
    {"frame": 0, "value": {"axis": [0, 1, 0], "degrees": 0}}, {"frame": 120, "value": {"axis": [0, 1, 0], "degrees": 360}}]}]}
write_scene("scenes/toys/turntable.json", spin)
