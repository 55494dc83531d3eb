# rtcli as a Blender render engine (docs/blender.md). Install: zip this folder (tools/blender/
# package.sh) and choose it in Preferences > Add-ons > Install, or link the folder into Blender's
# scripts/addons. The modules are imported on register, not here, so that tools/blender_export.py
# (and its tests, with a stand-in bpy) can import rtcli.export alone.
#
# Licence: Apache-2.0, as the rest of rtcli.
bl_info = {
    'name': 'rtcli',
    'author': 'the rtcli developers',
    'version': (0, 1, 0),
    'blender': (3, 4, 0),
    'location': 'Render Properties > Render Engine > rtcli',
    'description': 'Renders with rtcli (F12, animations) through a glTF export of the scene',
    'category': 'Render',
}


def _modules():
    from . import engine, properties, ui
    return properties, engine, ui


def register():
    for module in _modules():
        module.register()


def unregister():
    for module in reversed(_modules()):
        module.unregister()
