# Exports the open Blender scene as glTF 2.0 for rtcli, with area lights, bump maps and the world
# as extras: the exporter of the Blender add-on (tools/blender/rtcli/export.py), run by hand.
#
# Usage (docs/blender.md, "Exporting by hand"):
#   blender scene.blend --background --python tools/blender_export.py -- out.glb
# then: rtcli render out.glb --frame N (or the command the add-on keeps with "Keep Export").
# Material nodes rtcli cannot represent are listed on the console, one line per material.
#
# Licence: Apache-2.0, as the rest of rtcli.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'blender'))
from rtcli.export import export_for_rtcli  # noqa: E402


def export_with_warnings(path):
    import bpy
    from rtcli.material_check import warnings_for
    for warning in export_for_rtcli(path) + warnings_for(bpy.data.materials):
        print('rtcli: warning: ' + warning)


if __name__ == '__main__':
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    if not argv:
        raise SystemExit('usage: blender scene.blend --background --python tools/blender_export.py -- out.glb')
    export_with_warnings(argv[0])
