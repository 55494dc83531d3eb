#!/usr/bin/env python3
"""Writes the POV-Ray 3.7 twin of an rtcli scene file, for speed and image comparisons
(docs/benchmark.md, "Against POV-Ray"). Analytic shapes, groups, Phong materials, mirrors, glass,
CSG solids, point and rect lights, the perspective camera, the anti-aliasing settings and image
textures on planes are converted; anything else (meshes, other textures, glossy, spot and
directional lights, other cameras) is refused
by name, so a twin is never silently different.

  twin.py SCENE.json OUT.pov [--width W] [--height H]

prints the povray command line that renders the twin like `rtcli render SCENE --width W --height H`.

Conversion rules (rtcli -> POV-Ray):
- coordinates are kept; the camera's `right` vector is -x * aspect, which makes POV-Ray's view
  right-handed like rtcli's. fov (vertical) -> angle (horizontal) = 2 atan(tan(fov/2) aspect).
- M = T Rz Ry Rx S -> scale S, rotate x, rotate y, rotate z, translate T (POV-Ray applies them in
  order); group transforms wrap their children's.
- sphere -> sphere {0, 1}; cube -> box {-1, 1}; plane (the square x, z in [-1, 1]) -> polygon;
  cylinder (radius 1 about +z, z in [0, 1], capped) -> cylinder {0, z, 1}; cone (apex at 0, base
  radius 1 at z = 1) -> cone {0, 0, z, 1}.
- colour = ambient kd + sum of lights (kd n.l + ks (r.v)^shininess) + reflectivity R + ...:
  pigment kd (times 1 - transmission), finish { ambient <scene ambient> diffuse 1 phong ks
  phong_size shininess reflection reflectivity }; linear colours (assumed_gamma 1, sRGB output).
- transmission t and ior n -> pigment transmit t (coloured t with kd 0: filter, rgbf <t, 1>), interior { ior n }, reflection { R, R + t fresnel
  on } and conserve_energy: rtcli reflects R + t F at glass, F Fresnel's reflectance (Schlick's
  approximation; POV-Ray the exact terms). POV-Ray's fresnel scales between the two values: with
  one value alone (`reflection { 0 fresnel on }`) glass reflects nothing but total internal
  reflection, which made the twin trace half the rays rtcli does;
  absorption a -> interior fade_power 1001 (Beer's law) with fade_colour exp(-a).
- point light -> light_source, colour x intensity (attenuation must be [1, 0, 0]); rect light
  (corner, edges) -> an area_light of n x n points (n = sqrt(shadow_samples)), jittered, centred
  on the rectangle, every point sampled (no adaptive). POV-Ray's points light equally in all
  directions; rtcli's rectangle lights by the cosine at the light (one-sided).
- max_depth -> max_trace_level (+1: POV-Ray counts the camera ray); background -> background.
- antialias: none -> no +A; uniform n -> +AM1 +A0.0 +R n (every pixel n x n); adaptive
  (threshold t, depth d) -> +AM2 +A t +R d (POV-Ray's adaptive method, corners recursively).
"""
import argparse
import json
import math
import os
import sys


def fail(message):
    sys.exit("twin.py: error: %s" % message)


def vec(v):
    return "<%s>" % ", ".join("%.9g" % x for x in v)


def rgb(v):
    if isinstance(v, (int, float)):
        v = [v, v, v]
    return "rgb " + vec(v)


def transform(t):
    if not t:
        return ""
    out = []
    s = t.get("scale")
    if s is not None:
        out.append("scale " + (vec(s) if isinstance(s, list) else "%.9g" % s))
    r = t.get("rotate")
    if r is not None:
        for axis, a in zip("xyz", r):
            if a:
                out.append("rotate %s*%.9g" % (axis, a))
    if t.get("translate") is not None:
        out.append("translate " + vec(t["translate"]))
    if set(t) - {"scale", "rotate", "translate"}:
        fail("transform keys %s have no twin" % sorted(set(t) - {"scale", "rotate", "translate"}))
    return " ".join(out)


SHAPES = {
    "sphere": "sphere { 0, 1",
    "cube": "box { -1, 1",
    "plane": "polygon { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <-1, 0, -1>",
    "cylinder": "cylinder { 0, z, 1",
    "cone": "cone { 0, 0, z, 1",
}


def image_pigment(name, texture, folder):
    """A texture on a plane: its (u, v) = ((x + 1) / 2, (z + 1) / 2) times scale, the image's first
    row at v = 0; POV-Ray's image_map lies on x, y in [0, 1] with its first row at y = 1. The matrix
    takes the image's (X, Y, Z) to the plane's (2 X / su - 1, Z, -2 Y / sv - 1)."""
    if isinstance(texture, str):
        texture = {"file": texture}
    if set(texture) - {"file", "scale", "filter"} or texture.get("projection", "uv") != "uv":
        fail("texture of material %r: %s have no twin" % (name, sorted(set(texture) - {"file", "scale", "filter"})))
    su, sv = texture.get("scale", [1, 1]) if isinstance(texture.get("scale", 1), list) else [texture.get("scale", 1)] * 2
    path = os.path.abspath(os.path.join(folder, texture["file"]))
    kind = {".png": "png", ".jpg": "jpeg", ".jpeg": "jpeg"}.get(os.path.splitext(path)[1].lower())
    if kind is None:
        fail("texture %r: only PNG and JPEG have a twin" % texture["file"])
    return 'pigment { image_map { %s "%s" gamma srgb interpolate 2 } matrix <%.9g, 0, 0, 0, 0, %.9g, 0, 1, 0, -1, 0, -1> }' % (
        kind, path, 2.0 / su, -2.0 / sv)


def material(name, index, m, ambient, folder):
    known = {"kd", "ks", "shininess", "reflectivity", "transmission", "ior", "absorption", "texture"}
    if set(m) - known:
        fail("material %r: %s have no twin" % (name, sorted(set(m) - known)))
    if "texture" in m and ("kd" in m or "transmission" in m):
        fail("material %r: a texture with kd or transmission has no twin" % name)
    kd = m.get("kd", 0.8)
    kd = [kd] * 3 if isinstance(kd, (int, float)) else kd
    t = m.get("transmission", 0)
    t3 = [t] * 3 if isinstance(t, (int, float)) else t
    ks = m.get("ks", 0)
    if isinstance(ks, list):
        ks = max(ks)
    refl = m.get("reflectivity", 0)
    if refl == "ks":
        refl = min(1.0, ks)
    pigment = "pigment { rgbt <%.9g, %.9g, %.9g, %.9g> }" % (
        kd[0] * (1 - t3[0]), kd[1] * (1 - t3[1]), kd[2] * (1 - t3[2]), max(t3))
    if max(kd) == 0 and len(set(t3)) > 1:
        # Coloured glass: POV-Ray's filter passes light times the pigment's colour.
        pigment = "pigment { rgbf <%.9g, %.9g, %.9g, 1> }" % tuple(t3)
    if "texture" in m:
        pigment = image_pigment(name, m["texture"], folder)
    finish = "finish { ambient %s diffuse 1 phong %.9g phong_size %.9g" % (rgb(ambient), ks, m.get("shininess", 32))
    interior = ""
    if max(t3) > 0:
        refl3 = [refl] * 3 if isinstance(refl, (int, float)) else refl
        finish += " reflection { %s, %s fresnel on } conserve_energy" % (
            rgb(refl3), rgb([min(1.0, r + x) for r, x in zip(refl3, t3)]))
        interior = " interior { ior %.9g" % m.get("ior", 1.5)
        a = m.get("absorption")
        if a:
            a = [a] * 3 if isinstance(a, (int, float)) else a
            interior += " fade_power 1001 fade_distance 1 fade_color %s" % rgb([math.exp(-x) for x in a])
        interior += " }"
    elif refl:
        finish += " reflection { %s }" % rgb(refl)
    finish += " }"
    return "#declare M_%d = material { texture { %s %s }%s }  // %s" % (index, pigment, finish, interior, name)


CSG = {"union": "union", "intersection": "intersection", "difference": "difference", "merge": "merge"}


def node(n, names, textured, depth=1):
    """A shape, a group (union) or a CSG solid (POV-Ray's own four operations, each operand keeping
    its material, the cut surfaces of a difference showing the subtracted operand's, as rtcli's)."""
    pad = "  " * depth
    material = " material { M_%d }" % names[n["material"]] if "material" in n else ""
    if "children" in n:
        op = CSG.get(n.get("csg", "union"))
        if op is None:
            fail("csg %r has no twin" % n["csg"])
        body = "\n".join(node(c, names, textured, depth + 1) for c in n["children"])
        return "%s%s {\n%s\n%s %s %s\n%s}" % (pad, op, body, pad, material, transform(n.get("transform")), pad)
    if "shape" not in n:
        fail("node %r: only analytic shapes, groups and CSG have twins (not %s)" % (
            n.get("name", "?"), sorted(set(n) - {"name", "transform", "material"})))
    if n["shape"] not in SHAPES:
        fail("shape %r has no twin" % n["shape"])
    if n.get("material") in textured and n["shape"] != "plane":
        fail("a texture on a %s has no twin (only on a plane)" % n["shape"])
    return "%s%s%s %s }" % (pad, SHAPES[n["shape"]], material, transform(n.get("transform")))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--width", type=int)
    p.add_argument("--height", type=int)
    a = p.parse_args()
    s = json.load(open(a.scene))
    render = s.get("render", {})
    w, h = a.width or render.get("width", 640), a.height or render.get("height", 480)
    cam = s["camera"]
    if set(cam) - {"position", "look_at", "up", "fov"}:
        fail("camera keys %s have no twin" % sorted(set(cam) - {"position", "look_at", "up", "fov"}))
    aspect = w / h
    angle = 2 * math.degrees(math.atan(math.tan(math.radians(cam.get("fov", 45)) / 2) * aspect))
    ambient = s.get("ambient", [0, 0, 0])
    names = {name: i for i, name in enumerate(s.get("materials", {}))}
    out = ["// POV-Ray 3.7 twin of %s, written by tools/povray/twin.py" % a.scene,
           "#version 3.7;",
           "global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level %d }" % (render.get("max_depth", 5) + 1),
           "background { %s }" % rgb(s.get("background", [0, 0, 0])),
           "camera { perspective location %s sky %s up y right -x*%.9g angle %.9g look_at %s }" % (
               vec(cam["position"]), vec(cam.get("up", [0, 1, 0])), aspect, angle, vec(cam["look_at"]))]
    samples = render.get("shadow_samples", 16)
    for light in s.get("lights", []):
        colour = light.get("color", 1)
        colour = [colour] * 3 if isinstance(colour, (int, float)) else colour
        colour = [c * light.get("intensity", 1) for c in colour]
        if light.get("attenuation", [1, 0, 0]) != [1, 0, 0]:
            fail("light attenuation has no twin")
        if light["type"] == "point":
            out.append("light_source { %s %s }" % (vec(light["position"]), rgb(colour)))
        elif light["type"] == "rect":
            c, e1, e2 = light["corner"], light["edge1"], light["edge2"]
            centre = [c[i] + 0.5 * (e1[i] + e2[i]) for i in range(3)]
            n = max(1, round(math.sqrt(samples)))
            out.append("light_source { %s %s area_light %s, %s, %d, %d jitter }" % (
                vec(centre), rgb(colour), vec(e1), vec(e2), n, n))
        else:
            fail("%s lights have no twin" % light["type"])
    folder = os.path.dirname(os.path.abspath(a.scene))
    for name, m in s.get("materials", {}).items():
        out.append(material(name, names[name], m, ambient, folder))
    textured = {name for name, m in s.get("materials", {}).items() if "texture" in m}
    out += [node(n, names, textured, 0) for n in s["nodes"]]
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")
    aa = render.get("antialias", {})
    mode = aa.get("mode", "adaptive")
    flags = ""
    if mode == "uniform":
        flags = " +AM1 +A0.0 +R%d" % aa.get("samples", 2)
    elif mode == "adaptive":
        flags = " +AM2 +A%g +R%d" % (aa.get("threshold", 0.1), aa.get("max_depth", 3))
    print("povray +I%s +O%s.png +W%d +H%d +FN File_Gamma=sRGB -D -V +WT2%s" % (a.out, a.out[:-4], w, h, flags))


if __name__ == "__main__":
    main()
