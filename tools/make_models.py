#!/usr/bin/env python3
"""Writes the small glTF models the example scenes use (scenes/models/), from code, so the repo
holds no third-party assets. Standard library only. Run: python3 tools/make_models.py

  knot.glb   a (2,3) torus knot tube: indexed (UNSIGNED_SHORT), NORMAL and TEXCOORD_0, binary container
  gem.gltf   a faceted gem: non-indexed, no normals (flat shading), JSON + external gem.bin
  material_extensions.gltf  six spheres, one per ratified PBR extension (clearcoat, sheen, specular,
             anisotropy, iridescence, dispersion), all of them in extensionsRequired; + .bin
"""
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "scenes", "models")


def sub(a, b): return [a[i] - b[i] for i in range(3)]
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def norm(a):
    length = math.sqrt(sum(x * x for x in a))
    return [x / length for x in a]


def torus_knot(p=2, q=3, segments=240, sides=16, radius=0.28):
    def centre(t):
        r = 2.0 + math.cos(q * t)
        return [r * math.cos(p * t) * 0.33, math.sin(q * t) * 0.33, r * math.sin(p * t) * 0.33]
    positions, normals, uvs, indices = [], [], [], []
    for i in range(segments + 1):
        t = 2 * math.pi * i / segments
        c, c2 = centre(t), centre(t + 1e-3)
        tangent = norm(sub(c2, c))
        side = norm(cross(tangent, [0.0, 1.0, 0.0]))
        up = cross(side, tangent)
        for j in range(sides + 1):
            a = 2 * math.pi * j / sides
            n = [math.cos(a) * side[k] + math.sin(a) * up[k] for k in range(3)]
            positions.append([c[k] + radius * n[k] for k in range(3)])
            normals.append(n)
            uvs.append([i / segments, j / sides])
    for i in range(segments):
        for j in range(sides):
            a, b = i * (sides + 1) + j, (i + 1) * (sides + 1) + j
            indices += [a, b, a + 1, a + 1, b, b + 1]  # counter-clockwise seen from outside
    return positions, normals, uvs, indices


def gem(facets=10):
    crown, girdle, pavilion = 0.35, 0.0, -0.8
    top = [[0.55 * math.cos(2 * math.pi * k / facets), crown, 0.55 * math.sin(2 * math.pi * k / facets)] for k in range(facets)]
    mid = [[math.cos(2 * math.pi * (k + 0.5) / facets), girdle, math.sin(2 * math.pi * (k + 0.5) / facets)] for k in range(facets)]
    tris = []
    centre_top, tip = [0.0, crown, 0.0], [0.0, pavilion, 0.0]
    for k in range(facets):
        n = (k + 1) % facets
        tris += [centre_top, top[n], top[k]]            # table
        tris += [top[k], top[n], mid[k]]                 # crown facets
        tris += [top[n], mid[n], mid[k]]
        tris += [mid[k], mid[n], tip]                    # pavilion
    return tris


def bounds(points):
    return [min(p[i] for p in points) for i in range(3)], [max(p[i] for p in points) for i in range(3)]


def pack(fmt, rows):
    return b"".join(struct.pack(fmt, *row) for row in rows)


def pad4(data, byte=b"\0"):
    return data + byte * ((4 - len(data) % 4) % 4)


def write_knot():
    positions, normals, uvs, indices = torus_knot()
    chunks = [pad4(pack("<3f", positions)), pad4(pack("<3f", normals)), pad4(pack("<2f", uvs)),
              pad4(struct.pack("<%dH" % len(indices), *indices))]
    views, offset = [], 0
    for data, target in zip(chunks, [34962, 34962, 34962, 34963]):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(data), "target": target})
        offset += len(data)
    lo, hi = bounds(positions)
    doc = {
        "asset": {"version": "2.0", "generator": "rtcli tools/make_models.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "knot", "mesh": 0}],
        "meshes": [{"name": "knot", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                     "indices": 3, "material": 0}]}],
        "materials": [{"name": "copper", "pbrMetallicRoughness": {"baseColorFactor": [0.95, 0.64, 0.54, 1.0],
                                                                    "metallicFactor": 1.0, "roughnessFactor": 0.35}}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": len(indices), "type": "SCALAR"}],
        "bufferViews": views,
        "buffers": [{"byteLength": offset}],
    }
    json_chunk = pad4(json.dumps(doc, separators=(",", ":")).encode(), b" ")
    bin_chunk = b"".join(chunks)
    total = 12 + 8 + len(json_chunk) + 8 + len(bin_chunk)
    with open(os.path.join(OUT, "knot.glb"), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, total))
        f.write(struct.pack("<I4s", len(json_chunk), b"JSON") + json_chunk)
        f.write(struct.pack("<I4s", len(bin_chunk), b"BIN\0") + bin_chunk)
    return len(indices) // 3


def write_gem():
    points = gem()
    data = pack("<3f", points)
    lo, hi = bounds(points)
    doc = {
        "asset": {"version": "2.0", "generator": "rtcli tools/make_models.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "gem", "mesh": 0}],
        "meshes": [{"name": "gem", "primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
        "materials": [{"name": "emerald", "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.6, 0.3, 1.0],
                                                                     "metallicFactor": 0.0, "roughnessFactor": 0.1}}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3", "min": lo, "max": hi}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(data), "target": 34962}],
        "buffers": [{"uri": "gem.bin", "byteLength": len(data)}],
    }
    with open(os.path.join(OUT, "gem.bin"), "wb") as f:
        f.write(data)
    with open(os.path.join(OUT, "gem.gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    return len(points) // 3


def uv_sphere(rings=48, segments=96):
    """Unit sphere with normals, UVs and TANGENT (along increasing u: east), indexed."""
    positions, normals, uvs, tangents, indices = [], [], [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            positions.append(n)
            normals.append(n)
            uvs.append([j / segments, i / rings])
            tangents.append([-math.sin(phi), 0.0, -math.cos(phi), 1.0])
    for i in range(rings):
        for j in range(segments):
            a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            indices += [a, b, a + 1, a + 1, b, b + 1]
    return positions, normals, uvs, tangents, indices


EXTENSION_MATERIALS = [
    ("clearcoat", {"pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.04, 0.03, 1], "metallicFactor": 0.0,
                                            "roughnessFactor": 0.7},
                   "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.0}}}),
    ("sheen", {"pbrMetallicRoughness": {"baseColorFactor": [0.03, 0.02, 0.12, 1], "metallicFactor": 0.0,
                                        "roughnessFactor": 0.9},
               "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [0.9, 0.55, 1.0], "sheenRoughnessFactor": 0.35}}}),
    ("specular", {"pbrMetallicRoughness": {"baseColorFactor": [0.05, 0.05, 0.05, 1], "metallicFactor": 0.0,
                                           "roughnessFactor": 0.25},
                  "extensions": {"KHR_materials_specular": {"specularFactor": 1.0, "specularColorFactor": [6.0, 3.0, 0.6]},
                                 "KHR_materials_ior": {"ior": 1.8}}}),
    ("anisotropy", {"pbrMetallicRoughness": {"baseColorFactor": [0.92, 0.92, 0.95, 1], "metallicFactor": 1.0,
                                             "roughnessFactor": 0.35},
                    "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.9, "anisotropyRotation": 0.0}}}),
    ("iridescence", {"pbrMetallicRoughness": {"baseColorFactor": [0.02, 0.02, 0.02, 1], "metallicFactor": 0.0,
                                              "roughnessFactor": 0.1},
                     "extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 1.0, "iridescenceIor": 1.33,
                                                                  "iridescenceThicknessMaximum": 420}}}),
    ("dispersion", {"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0, "roughnessFactor": 0.0},
                    "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                   "KHR_materials_ior": {"ior": 1.6},
                                   "KHR_materials_dispersion": {"dispersion": 8.0}}}),
]


def write_material_spheres():
    positions, normals, uvs, tangents, indices = uv_sphere()
    chunks = [pad4(pack("<3f", positions)), pad4(pack("<3f", normals)), pad4(pack("<2f", uvs)),
              pad4(pack("<4f", tangents)), pad4(struct.pack("<%dH" % len(indices), *indices))]
    views, offset = [], 0
    for data, target in zip(chunks, [34962, 34962, 34962, 34962, 34963]):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(data), "target": target})
        offset += len(data)
    lo, hi = bounds(positions)
    names = sorted({ext for _, m in EXTENSION_MATERIALS for ext in m["extensions"]})
    nodes, meshes, materials = [], [], []
    for k, (name, material) in enumerate(EXTENSION_MATERIALS):
        materials.append(dict(name=name, **material))
        meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2,
                                                                      "TANGENT": 3}, "indices": 4, "material": k}]})
        nodes.append({"name": name, "mesh": k, "translation": [2.2 * (k % 3) - 2.2, 0.0, 2.2 * (k // 3) - 1.1]})
    doc = {
        "asset": {"version": "2.0", "generator": "rtcli tools/make_models.py"},
        "extensionsUsed": names, "extensionsRequired": names,
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes, "meshes": meshes, "materials": materials,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 3, "componentType": 5126, "count": len(tangents), "type": "VEC4"},
            {"bufferView": 4, "componentType": 5123, "count": len(indices), "type": "SCALAR"}],
        "bufferViews": views,
        "buffers": [{"uri": "material_extensions.bin", "byteLength": offset}],
    }
    with open(os.path.join(OUT, "material_extensions.bin"), "wb") as f:
        f.write(b"".join(chunks))
    with open(os.path.join(OUT, "material_extensions.gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    return len(materials)


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    print("knot.glb: %d triangles" % write_knot())
    print("gem.gltf: %d triangles" % write_gem())
    print("material_extensions.gltf: %d materials" % write_material_spheres())
