#!/usr/bin/env python3
# Writes scenes/gallery/: the small scenes the gallery (tools/gallery/sections.py) compares where
# one scene must change in a way no command-line option does: the glossy width a of one slab
# (0, 0.05, 0.15, 0.3), and one texture under each projection (uv, planar, spherical,
# cylindrical). Each set differs only in that one key. Run from the repository root.
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_json import T, write_scene  # noqa: E402

OUT = "scenes/gallery"


def base(render, camera, materials, nodes, lights, background):
    return {"$schema": "../../schemas/scene.schema.json", "render": render, "camera": camera,
            "background": background, "ambient": [0.1, 0.1, 0.12], "materials": materials,
            "lights": lights, "nodes": nodes}


def glossy(width):
    """A polished slab reflecting three blocks and a checkered wall: the further the reflected
    thing, the more a wider lobe blurs it."""
    slab = {"kd": [0.08, 0.07, 0.06], "ks": 0.5, "shininess": 120, "reflectivity": 0.8, "glossy": width}
    materials = {"slab": slab, "wall": {"texture": {"file": "../textures/checker.png", "scale": [4, 2]}},
                 "red": {"kd": [0.8, 0.12, 0.1], "ks": 0.3, "shininess": 60},
                 "green": {"kd": [0.15, 0.6, 0.2], "ks": 0.3, "shininess": 60},
                 "blue": {"kd": [0.12, 0.2, 0.75], "ks": 0.3, "shininess": 60}}
    nodes = [{"name": "slab", "shape": "cube", "material": "slab", "transform": T(t=[0, -0.05, 0], s=[3, 0.05, 2])},
             {"name": "wall", "shape": "plane", "material": "wall",
              "transform": T(t=[0, 1.5, -2], r=[90, 0, 0], s=[3, 1, 1.5])},
             {"name": "red block", "shape": "cube", "material": "red", "transform": T(t=[-1.2, 0.4, -1], s=0.4)},
             {"name": "green cylinder", "shape": "cylinder", "material": "green",
              "transform": T(t=[0, 0, -0.6], r=[-90, 0, 0], s=[0.35, 0.35, 0.9])},
             {"name": "blue sphere", "shape": "sphere", "material": "blue", "transform": T(t=[1.2, 0.45, -0.2], s=0.45)}]
    render = {"width": 400, "height": 225, "max_depth": 3, "seed": 1, "glossy_samples": 16,
              "antialias": {"mode": "uniform", "samples": 2}}
    camera = {"position": [0, 1.1, 4.2], "look_at": [0, 0.35, -0.4], "up": [0, 1, 0], "fov": 40}
    lights = [{"type": "point", "position": [-3, 5, 4], "color": [1, 0.97, 0.92], "intensity": 0.9}]
    # A dim sky, so the slab shows the reflected things rather than the sky.
    return base(render, camera, materials, nodes, lights, [0.22, 0.24, 0.28])


def projection(kind):
    """The UV grid on a sphere, a cube and a cylinder, all mapped one way."""
    texture = {"file": "../textures/uv_grid.png"}
    if kind != "uv":
        texture["projection"] = kind
    materials = {"grid": {"texture": texture, "ks": 0.25, "shininess": 60},
                 "floor": {"kd": [0.55, 0.52, 0.48]}}
    nodes = [{"name": "floor", "shape": "plane", "material": "floor", "transform": T(s=[6, 1, 4])},
             {"name": "sphere", "shape": "sphere", "material": "grid", "transform": T(t=[-1.7, 0.8, 0], r=[0, -30, 0], s=0.8)},
             {"name": "cube", "shape": "cube", "material": "grid", "transform": T(t=[0, 0.7, 0], r=[0, 35, 0], s=0.7)},
             {"name": "cylinder", "shape": "cylinder", "material": "grid",
              "transform": T(t=[1.7, 0, 0], r=[-90, -30, 0], s=[0.6, 0.6, 1.5])}]
    render = {"width": 400, "height": 225, "max_depth": 2, "seed": 1, "antialias": {"mode": "adaptive"}}
    camera = {"position": [0, 2.4, 6.2], "look_at": [0, 0.7, 0], "up": [0, 1, 0], "fov": 38}
    lights = [{"type": "point", "position": [-3, 6, 6], "color": [1, 0.97, 0.92], "intensity": 0.85},
              {"type": "point", "position": [5, 3, 4], "color": [0.6, 0.65, 0.75], "intensity": 0.35}]
    return base(render, camera, materials, nodes, lights, [0.55, 0.65, 0.8])


os.makedirs(OUT, exist_ok=True)
for a in ("0", "0.05", "0.15", "0.3"):
    write_scene(os.path.join(OUT, "glossy_%s.json" % a), glossy(float(a)))
for kind in ("uv", "planar", "spherical", "cylindrical"):
    write_scene(os.path.join(OUT, "projection_%s.json" % kind), projection(kind))
print("wrote %s: glossy_{0,0.05,0.15,0.3}.json, projection_{uv,planar,spherical,cylindrical}.json" % OUT)
