#!/usr/bin/env python3
# Writes scenes/stereo.json (a red-cyan anaglyph: toys receding along a table, the plane of zero
# parallax at the middle one) and scenes/panorama.json (the same room all round, as a 360-degree
# equirectangular image; `--stereo top_bottom` makes it omni-directional stereo for VR viewers).
# Run from the repository root.
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_json import T, write_scene  # noqa: E402


materials = {
    "floor": {"texture": {"file": "textures/wood.png", "scale": [4, 4]}, "ks": 0.1, "shininess": 30},
    "wall": {"texture": {"file": "textures/bricks_colour.png", "scale": [6, 2]}, "normal_map": {"file": "textures/bricks_normal.png", "scale": [6, 2]}},
    "red": {"kd": [0.75, 0.12, 0.1], "ks": 0.4, "shininess": 60},
    "blue": {"kd": [0.1, 0.25, 0.75], "ks": 0.4, "shininess": 60},
    "yellow": {"kd": [0.85, 0.7, 0.15], "ks": 0.3, "shininess": 40},
    "green": {"kd": [0.15, 0.6, 0.25], "ks": 0.3, "shininess": 40},
    "mirror": {"kd": 0.05, "ks": 0.8, "shininess": 200, "reflectivity": 0.85},
    "glass": {"kd": 0, "ks": 0.6, "shininess": 400, "transmission": 1, "ior": 1.5},
}
toys = [
    {"name": "near ball", "shape": "sphere", "material": "red", "transform": T(t=[-0.9, 0.35, 2.2], s=0.35)},
    {"name": "block", "shape": "cube", "material": "blue", "transform": T(t=[0.7, 0.3, 1.0], r=[0, 30, 0], s=0.3)},
    {"name": "glass ball", "shape": "sphere", "material": "glass", "transform": T(t=[-0.2, 0.45, 0.0], s=0.45)},
    {"name": "cone", "shape": "cone", "material": "yellow", "transform": T(t=[1.3, 0.9, -1.4], r=[90, 0, 0], s=[0.4, 0.4, 0.9])},
    {"name": "mirror ball", "shape": "sphere", "material": "mirror", "transform": T(t=[-1.4, 0.6, -2.6], s=0.6)},
    {"name": "drum", "shape": "cylinder", "material": "green", "transform": T(t=[0.4, 0, -4.0], r=[-90, 0, 0], s=[0.5, 0.5, 0.9])},
]
room = [
    {"name": "floor", "shape": "plane", "material": "floor", "transform": T(s=[8, 1, 8])},
    {"name": "back wall", "shape": "plane", "material": "wall", "transform": T(t=[0, 2.5, -6], r=[90, 0, 0], s=[8, 1, 2.5])},
]
lights = [
    {"type": "rect", "corner": [-1, 4, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2], "color": [1, 0.97, 0.92], "intensity": 0.8},
    {"type": "point", "position": [4, 3, 6], "color": [0.3, 0.32, 0.38]},
]
stereo = {
    "$schema": "../schemas/scene.schema.json",
    "render": {"width": 800, "height": 450, "max_depth": 6, "seed": 1, "shadow_samples": 16,
               "antialias": {"mode": "adaptive", "threshold": 0.08, "max_depth": 2}},
    "camera": {"position": [0, 1.1, 5.2], "look_at": [0, 0.5, 0], "fov": 42,
               "stereo": {"mode": "anaglyph", "eye_separation": 0.1}},
    "background": [0.08, 0.09, 0.12], "ambient": 0.06,
    "materials": materials, "lights": lights, "nodes": room + toys,
}
write_scene("scenes/stereo.json", stereo)

# All round: walls on every side, the toys in a ring about the camera.
walls = [
    {"name": "floor", "shape": "plane", "material": "floor", "transform": T(s=[8, 1, 8])},
    {"name": "ceiling", "shape": "plane", "material": "ceiling", "transform": T(t=[0, 3.2, 0], r=[180, 0, 0], s=[8, 1, 8])},
] + [{"name": "wall %d" % i, "shape": "plane", "material": "wall",
      "transform": T(t=t, r=r, s=[6, 1, 1.6])} for i, (t, r) in enumerate([
          ([0, 1.6, -6], [90, 0, 0]), ([0, 1.6, 6], [-90, 0, 0]), ([-6, 1.6, 0], [90, 90, 0]), ([6, 1.6, 0], [90, -90, 0])])]
ring = []
for i, toy in enumerate(toys):
    a = 2 * math.pi * i / len(toys)
    t = dict(toy)
    tr = dict(toy["transform"])
    d = 1.6 + 0.5 * i
    tr["translate"] = [round(d * math.sin(a), 3), tr["translate"][1], round(-d * math.cos(a), 3)]
    t["transform"] = tr
    ring.append(t)
pano_materials = dict(materials)
pano_materials["ceiling"] = {"kd": 0.7}
panorama = {
    "$schema": "../schemas/scene.schema.json",
    "render": {"width": 1024, "height": 512, "max_depth": 6, "seed": 1, "shadow_samples": 16,
               "antialias": {"mode": "adaptive", "threshold": 0.08, "max_depth": 2}},
    "camera": {"position": [0, 1.2, 0], "look_at": [0, 1.2, -1], "projection": "equirectangular",
               "stereo": {"mode": "top_bottom", "convergence": 3}},
    "background": [0.08, 0.09, 0.12], "ambient": 0.08,
    "materials": pano_materials,
    "lights": [{"type": "rect", "corner": [1.5, 3.1, -2.5], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "color": [1, 0.97, 0.92], "intensity": 1.6},
               {"type": "point", "position": [-2, 2.5, 2], "color": [0.45, 0.45, 0.5]}],
    "nodes": walls + ring,
}
write_scene("scenes/panorama.json", panorama)
