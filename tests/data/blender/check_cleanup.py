# Runs tools/blender_export.py against a stand-in for Blender's bpy module and checks that the
# custom properties it sets for the export are there during the export and gone after it (or
# given back their earlier values), also when the export fails. Run by tests/tools/test_blender_export.cpp:
#   python3 tests/data/blender/check_cleanup.py OUT_FOLDER
import importlib.util
import os
import sys
import types

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..', '..'))


class Block(dict):
    """An ID block with custom properties (block[key]) and attributes."""

    def __init__(self, **attributes):
        super().__init__()
        self.__dict__.update(attributes)


def make_bpy(export):
    area = Block(type='AREA', shape='RECTANGLE', size=2.0, size_y=1.0, color=(1.0, 0.9, 0.8), energy=150.0)
    softbox = Block(type='LIGHT', data=area, name='Softbox')
    softbox['rtcli_area_light'] = {'shape': 'OLD'}  # the user's own, from an earlier session
    lamp = Block(type='LIGHT', data=Block(type='AREA', shape='SQUARE', size=1.0, color=(1, 1, 1), energy=50.0),
                 name='Lamp')
    box = Block(type='MESH', name='Box')
    box['note'] = 'keep me'
    material = Block(use_nodes=False, name='Red')
    bpy = types.ModuleType('bpy')
    scene = Block(objects=[softbox, lamp, box], world=None)
    bpy.context = types.SimpleNamespace(scene=scene)
    bpy.data = types.SimpleNamespace(materials=[material])
    bpy.path = types.SimpleNamespace(abspath=lambda p: p)
    bpy.ops = types.SimpleNamespace(export_scene=types.SimpleNamespace(gltf=export))
    return bpy, softbox, lamp, box


def load_exporter():
    for name in [m for m in sys.modules if m == 'rtcli' or m.startswith('rtcli.')]:
        del sys.modules[name]  # imported again against this stand-in bpy
    spec = importlib.util.spec_from_file_location('blender_export', os.path.join(REPO, 'tools', 'blender_export.py'))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main():
    out = os.path.join(sys.argv[1] if len(sys.argv) > 1 else '.', 'cleanup.glb')
    seen = {}

    def export(**settings):
        seen['softbox'] = dict(softbox.get('rtcli_area_light', {}))
        seen['lamp'] = 'rtcli_area_light' in lamp
        seen['extras'] = settings.get('export_extras')
        seen['world'] = dict(sys.modules['bpy'].context.scene.get('rtcli_world', {}))

    bpy, softbox, lamp, box = make_bpy(export)
    sys.modules['bpy'] = bpy
    exporter = load_exporter()
    exporter.export_for_rtcli(out)
    assert seen['softbox']['power'] == 150.0 and seen['lamp'] and seen['extras'], seen
    assert seen['world'] == {'color': [0.0, 0.0, 0.0], 'strength': 1.0}, seen  # no world: black, as Cycles
    assert 'rtcli_world' not in bpy.context.scene, dict(bpy.context.scene)
    assert softbox['rtcli_area_light'] == {'shape': 'OLD'}, softbox  # given back
    assert 'rtcli_area_light' not in lamp, lamp  # removed
    assert dict(box) == {'note': 'keep me'}, box  # untouched

    # A failing export leaves the objects as they were too.
    def failing(**settings):
        raise RuntimeError('export failed')

    bpy, softbox, lamp, box = make_bpy(failing)
    sys.modules['bpy'] = bpy
    exporter = load_exporter()
    try:
        exporter.export_for_rtcli(out)
        raise AssertionError('the failure was swallowed')
    except RuntimeError:
        pass
    assert softbox['rtcli_area_light'] == {'shape': 'OLD'} and 'rtcli_area_light' not in lamp
    print('blender_export cleanup: ok')


if __name__ == '__main__':
    main()
