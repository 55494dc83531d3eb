# rtcli's float EXR as Blender's render passes: rows flipped (Blender's start at the bottom), the
# colour given an alpha of 1, rtcli's normals (glTF's Y-up world) turned into Blender's Z-up
# world, and its depth (the distance along each camera ray, 1e10 where no surface is) made
# Blender's: the distance along the camera's axis for a perspective camera, as Cycles writes it.
#
# Licence: Apache-2.0, as the rest of rtcli.
import json
import struct

import numpy

from .exr import read_exr

FAR_AWAY = 1e10  # rtcli's and Cycles' depth where no surface is


def gltf_camera(glb_path, node_name):
    """The camera of the node called node_name in a .glb file: (type, yfov or None)."""
    with open(glb_path, 'rb') as f:
        head = f.read(20)
        length = struct.unpack_from('<I', head, 12)[0]
        document = json.loads(f.read(length))
    for node in document.get('nodes', []):
        if node.get('name') == node_name and 'camera' in node:
            camera = document['cameras'][node['camera']]
            if camera.get('type') == 'perspective':
                return 'perspective', camera['perspective']['yfov']
            return camera.get('type'), None
    return None, None


def axis_depth_factor(width, height, yfov):
    """Per pixel (rows top first): the cosine between its central ray and the camera's axis."""
    tan_y = numpy.tan(0.5 * yfov)
    tan_x = tan_y * width / height
    x = (2.0 * (numpy.arange(width) + 0.5) / width - 1.0) * tan_x
    y = (1.0 - 2.0 * (numpy.arange(height) + 0.5) / height) * tan_y
    return 1.0 / numpy.sqrt(1.0 + x[None, :] ** 2 + y[:, None] ** 2)


def load_passes(exr_path, camera=(None, None)):
    """{Blender pass name: float32 array [height * width, channels], bottom row first}."""
    width, height, planes = read_exr(exr_path)

    def stack(names):
        return numpy.stack([numpy.flipud(planes[n]) for n in names], axis=-1).reshape(width * height, len(names))

    passes = {}
    rgb = stack(['R', 'G', 'B'])
    passes['Combined'] = numpy.concatenate([rgb, numpy.ones((width * height, 1), numpy.float32)], axis=1)
    if 'albedo.R' in planes:
        passes['Albedo'] = stack(['albedo.R', 'albedo.G', 'albedo.B'])
    if 'normal.X' in planes:
        n = stack(['normal.X', 'normal.Y', 'normal.Z'])
        passes['Normal'] = numpy.stack([n[:, 0], -n[:, 2], n[:, 1]], axis=-1)  # glTF (x, y, z) is Blender's (x, -z, y)
    if 'depth.Z' in planes:
        depth = planes['depth.Z']
        kind, yfov = camera
        if kind == 'perspective' and yfov:
            hit = depth < FAR_AWAY
            depth = numpy.where(hit, depth * axis_depth_factor(width, height, yfov), FAR_AWAY)
        passes['Depth'] = numpy.flipud(depth).reshape(width * height, 1).astype(numpy.float32)
    return width, height, passes
