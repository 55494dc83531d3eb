#!/usr/bin/env python3
# Writes scenes/csg.json: the CSG showcase (a lens, a die with sunken pips, a hollow glass
# sphere, a merged blob beside the same blob as a union, a pipe). Run from the repository root.
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_json import T, write_scene  # noqa: E402

half = 0.6
pip_r = 0.12
faces = {  # axis, sign, pips (u, v offsets in units of 0.3)
    (1, 1): [(-1, -1), (1, 1), (0, 0), (-1, 1), (1, -1)],         # top: 5
    (1, -1): [(-1, -1), (1, 1)],                                  # bottom: 2
    (2, 1): [(0, 0)],                                             # front: 1
    (2, -1): [(-1, -1), (-1, 0), (-1, 1), (1, -1), (1, 0), (1, 1)],  # back: 6
    (0, 1): [(-1, -1), (0, 0), (1, 1)],                           # right: 3
    (0, -1): [(-1, -1), (-1, 1), (1, -1), (1, 1)],                # left: 4
}
pips = []
for (axis, sign), offsets in faces.items():
    u, v = (axis + 1) % 3, (axis + 2) % 3
    for a, b in offsets:
        p = [0.0, 0.0, 0.0]
        p[axis] = sign * half
        p[u] = 0.27 * a
        p[v] = 0.27 * b
        pips.append({"shape": "sphere", "material": "pip", "transform": T(t=[round(x, 4) for x in p], s=pip_r)})

def blob(op, x, name):
    return {"name": name, "csg": op, "material": "amber glass", "transform": T(t=[x, 0.62, 0.6]),
            "children": [
                {"shape": "sphere", "transform": T(t=[-0.28, 0, 0], s=0.5)},
                {"shape": "sphere", "transform": T(t=[0.28, 0, 0], s=0.5)},
                {"shape": "sphere", "transform": T(t=[0, 0.42, 0], s=0.4)}]}

scene = {
    "$schema": "../schemas/scene.schema.json",
    "render": {"width": 800, "height": 450, "max_depth": 10, "seed": 1, "shadow_samples": 16,
               "antialias": {"mode": "adaptive", "threshold": 0.08, "max_depth": 2}},
    "camera": {"position": [0, 2.6, 8.5], "look_at": [0, 0.8, 0], "fov": 40},
    "background": [0.08, 0.09, 0.12],
    "ambient": 0.08,
    "materials": {
        "floor": {"texture": {"file": "textures/wood.png", "scale": [3, 3]}, "ks": 0.1, "shininess": 30},
        "wall": {"texture": {"file": "textures/checker.png", "scale": [5, 2.5]}, "ks": 0.05},
        "glass": {"kd": 0, "ks": 0.6, "shininess": 400, "transmission": 1, "ior": 1.5},
        "amber glass": {"kd": 0, "ks": 0.6, "shininess": 400, "transmission": [1, 0.8, 0.45], "ior": 1.5},
        "ivory": {"kd": [0.9, 0.88, 0.8], "ks": 0.3, "shininess": 60},
        "pip": {"kd": [0.05, 0.05, 0.06], "ks": 0.2, "shininess": 40},
        "copper": {"kd": [0.35, 0.15, 0.08], "ks": [0.6, 0.4, 0.3], "shininess": 80, "reflectivity": [0.55, 0.3, 0.2]},
        "copper inside": {"kd": [0.2, 0.1, 0.06], "ks": 0.2, "shininess": 20}
    },
    "lights": [
        {"type": "rect", "corner": [-2.5, 6, 1.5], "edge1": [2, 0, 0], "edge2": [0, 0, 2], "color": [1, 0.97, 0.92], "intensity": 0.75},
        {"type": "point", "position": [5, 4, 8], "color": [0.35, 0.38, 0.45]}
    ],
    "nodes": [
        {"name": "floor", "shape": "plane", "material": "floor", "transform": T(s=[9, 1, 5])},
        {"name": "wall", "shape": "plane", "material": "wall", "transform": T(t=[0, 3, -2.5], r=[90, 0, 0], s=[9, 1, 3])},
        # A biconvex lens: two spheres of radius 2.5 whose centres are 4.4 apart (0.6 thick, rim 1.19).
        {"name": "lens", "csg": "intersection", "material": "glass", "transform": T(t=[-3.7, 1.2, 0], r=[0, 20, 0], s=0.75),
         "children": [{"shape": "sphere", "transform": T(t=[0, 0, -2.2], s=2.5)},
                      {"shape": "sphere", "transform": T(t=[0, 0, 2.2], s=2.5)}]},
        {"name": "lens stand", "shape": "cylinder", "material": "copper", "transform": T(t=[-3.7, 0, 0], r=[-90, 0, 0], s=[0.05, 0.05, 0.32])},
        {"name": "die", "csg": "difference", "transform": T(t=[-1.8, half, 0.9], r=[0, 28, 0]),
         "children": [{"csg": "intersection", "material": "ivory",
                       "children": [{"shape": "cube", "transform": T(s=half)},
                                    {"shape": "sphere", "transform": T(s=half * 1.38)}]}] + pips},
        {"name": "hollow glass sphere", "csg": "difference", "material": "glass", "transform": T(t=[0.1, 0.85, -0.3]),
         "children": [{"shape": "sphere", "transform": T(s=0.85)}, {"shape": "sphere", "transform": T(s=0.7)}]},
        blob("merge", 1.85, "merged blob"),
        blob("union", 3.45, "union blob"),
        {"name": "pipe", "csg": "difference", "transform": T(t=[1.2, 0.32, 2.3], r=[0, -60, 0]),
         "children": [{"shape": "cylinder", "material": "copper", "transform": T(t=[0, 0, -0.6], s=[0.32, 0.32, 1.2])},
                      {"shape": "cylinder", "material": "copper inside", "transform": T(t=[0, 0, -0.7], s=[0.22, 0.22, 1.4])}]}
    ]
}
write_scene("scenes/csg.json", scene)
