"""F12 in Blender's window (under Xvfb, headless): there the render runs in a job thread, and the
add-on exports on the main thread. Run by tests/tools/test_blender_addon.cpp where xvfb-run is:

  xvfb-run -a -s '-screen 0 1280x720x24' blender --factory-startup OUT/fixture.blend \
      --python tests/data/blender/ui_test.py -- OUT RTCLI

(OUT/fixture.blend from addon_test.py's "blend" case.) Invokes the render as F12 does, waits for
it (saved by Blender as OUT/ui.exr, its render output), compares it with `rtcli render` of the same scene
exported by hand, and takes a screenshot of the window, the render in its Image Editor and the
engine's settings beside it: OUT/blender.png (docs/images/blender-addon.png is one). Prints
"addon ui: ok" and quits.
"""
import importlib.util
import os
import subprocess
import sys

import addon_utils
import bpy
import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..', '..'))
argv = sys.argv[sys.argv.index('--') + 1:]
OUT, RTCLI = os.path.abspath(argv[0]), os.path.abspath(argv[1])
spec = importlib.util.spec_from_file_location('rtcli_exr', os.path.join(REPO, 'tools', 'blender', 'rtcli', 'exr.py'))
exr = importlib.util.module_from_spec(spec)
spec.loader.exec_module(exr)
state = {'done': False, 'status': 1}


def finish(status, message):
    print(message)
    state['status'] = status
    bpy.ops.wm.quit_blender()  # the exit status comes from the atexit hook below


def completed(*_):
    state['done'] = True


def start():
    bpy.context.preferences.view.render_display_type = 'AREA'  # the render in the main window
    window = bpy.context.window_manager.windows[0]
    for area in window.screen.areas:
        if area.type == 'PROPERTIES':
            area.spaces[0].context = 'RENDER'
    bpy.app.handlers.render_complete.append(completed)
    scene = bpy.context.scene
    scene.render.image_settings.file_format = 'OPEN_EXR'  # Blender's own output: linear, 32-bit
    scene.render.image_settings.color_depth = '32'
    scene.render.filepath = os.path.join(OUT, 'ui.exr')
    with bpy.context.temp_override(window=window):
        bpy.ops.render.render('INVOKE_DEFAULT', write_still=True)  # as F12, then saved as with -o
    bpy.app.timers.register(wait, first_interval=0.5)


def wait():
    if not state['done']:
        return 0.25
    bpy.app.timers.register(check, first_interval=1.0)  # let the window redraw the result
    return None


def check():
    window = bpy.context.window_manager.windows[0]
    with bpy.context.temp_override(window=window, area=window.screen.areas[0]):
        bpy.ops.screen.screenshot(filepath=os.path.join(OUT, 'blender.png'))
    glb = os.path.join(OUT, 'hand', 'scene.glb')
    spec = importlib.util.spec_from_file_location('blender_export', os.path.join(REPO, 'tools', 'blender_export.py'))
    exporter = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(exporter)
    exporter.export_for_rtcli(glb)
    subprocess.run([RTCLI, 'render', glb, '-o', os.path.join(OUT, 'hand.exr'), '--exr-float', '--frame', '1', '--fps',
                    '24', '--width', '640', '--height', '360', '--integrator', 'path', '--spp', '32', '--max-depth', '12', '--camera', 'Camera',
                    '-q'], check=True)
    got = exr.read_exr(os.path.join(OUT, 'ui.exr'))[2]
    want = exr.read_exr(os.path.join(OUT, 'hand.exr'))[2]
    differ = sum(int((got[c] != want[c]).sum()) for c in 'RGB')
    shot = os.path.isfile(os.path.join(OUT, 'blender.png'))
    message = 'addon ui: F12 in the window: %d of %d values differ from rtcli\'s own render; screenshot %s' % (
        differ, 3 * want['R'].size, 'written' if shot else 'missing')
    finish(0 if differ == 0 and shot else 1, message + ('\naddon ui: ok' if differ == 0 and shot else ''))
    return None


def exit_status():
    os._exit(state['status'])


import atexit  # noqa: E402

atexit.register(exit_status)
addon_utils.enable('rtcli', default_set=True)
bpy.context.preferences.addons['rtcli'].preferences.executable = RTCLI
bpy.app.timers.register(start, first_interval=1.0)
