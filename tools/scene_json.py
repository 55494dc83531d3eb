"""Helpers the scene generators share (tools/make_*_scene*.py): transforms and writing a scene."""
import json


def T(t=None, r=None, s=None):
    """A node transform: translate, rotate (degrees), scale; only the parts given."""
    d = {}
    if t is not None:
        d["translate"] = t
    if r is not None:
        d["rotate"] = r
    if s is not None:
        d["scale"] = s
    return d


def write_scene(path, scene):
    with open(path, "w") as f:
        f.write(json.dumps(scene, indent=2) + "\n")
