"""The Blender add-on (tools/blender/rtcli) end to end, in Blender itself; run by
tests/tools/test_blender_addon.cpp where Blender is installed:

  BLENDER_USER_SCRIPTS=OUT/scripts blender -b --factory-startup --python-exit-code 1 \
      --python tests/data/blender/addon_test.py -- CASE OUT RTCLI

Each case installs the add-on from its zip (tools/blender/package.py) into OUT/scripts, builds the
fixture scene (make_fixture.py), renders with the engine "RTCLI" and prints "addon CASE: ok":
  still      frame 1 with every pass; its pixels against `rtcli render` of the same scene exported
             by hand (tools/blender_export.py): the colour and albedo bit for bit, the normal and
             depth as Blender's (turned to Z-up; along the camera's axis)
  animation  frames 1-5 step 2 (bpy.ops.render.render(animation=True), as -a): three frames, each
             the same as `rtcli render --frame N` of the hand export, and different from the others
  error      a world image that is not an image: rtcli's located error reaches Blender's report;
             a missing executable is named
  cycles     a portrait image (sensor fit), a unit scale of 0.01 and a world colour: rtcli through the
             add-on against Cycles, RMSE of the display values
  environment  an Environment Texture turned by a Mapping node, seen in two directions: against Cycles
  blend      the fixture saved with the engine chosen (and exported by hand), for ui_test.py and
             `blender -b fixture.blend -E RTCLI -a`
  heavy      a render that would take hours, for cancel_test.py to cancel
"""
import importlib.util
import math
import os
import struct
import subprocess
import sys
import zlib

import addon_utils
import bpy
import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..', '..'))


def load(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# The add-on's EXR reader, used on Blender's files too; loaded by path under its own name, so that
# the module "rtcli" is the add-on installed from the zip.
read_exr = load('rtcli_exr', os.path.join(REPO, 'tools', 'blender', 'rtcli', 'exr.py')).read_exr


def setup(out, rtcli, width, height):
    package = load('package', os.path.join(REPO, 'tools', 'blender', 'package.py'))
    bpy.ops.wm.read_factory_settings(use_empty=True)  # before the add-on: this resets preferences
    load('make_fixture', os.path.join(HERE, 'make_fixture.py')).build(out)
    bpy.ops.preferences.addon_install(filepath=package.package(os.path.join(out, 'rtcli-blender.zip')),
                                      overwrite=True)
    addon_utils.enable('rtcli', default_set=True)
    assert 'rtcli' in bpy.context.preferences.addons, 'the add-on did not enable'
    bpy.context.preferences.addons['rtcli'].preferences.executable = rtcli
    scene = bpy.context.scene
    scene.render.engine = 'RTCLI'
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = width, height, 100
    scene.rtcli.samples = 16
    scene.render.image_settings.file_format = 'OPEN_EXR_MULTILAYER'
    scene.render.image_settings.color_depth = '32'
    return scene


def hand_render(out, rtcli, frame, width, height, aovs='albedo,normal,depth'):
    """The scene exported by hand and rendered by rtcli directly, with the add-on's settings."""
    folder = os.path.join(out, 'hand')
    os.makedirs(folder, exist_ok=True)
    glb = os.path.join(folder, 'scene.glb')
    if not os.path.exists(glb):
        load('blender_export', os.path.join(REPO, 'tools', 'blender_export.py')).export_with_warnings(glb)
    exr = os.path.join(folder, 'frame%d.exr' % frame)
    subprocess.run([rtcli, 'render', glb, '-o', exr, '--exr-float', '--frame', str(frame), '--fps', '24',
                    '--width', str(width), '--height', str(height), '--integrator', 'path', '--spp', '16',
                    '--max-depth', '12', '--camera', 'Camera', '-q'] + (['--aov', aovs] if aovs else []), check=True)
    return read_exr(exr)[2]


def blender_planes(path):
    """A multilayer EXR Blender saved: {pass.channel: rows top first}."""
    return {k.split('.', 1)[1]: v for k, v in read_exr(path)[2].items()}


def same(name, got, expected):
    diff = numpy.abs(got.astype(numpy.float64) - expected.astype(numpy.float64))
    print('addon: %-10s %d pixels, %d differ, largest difference %.3g' % (name, got.size, int((diff > 0).sum()),
                                                                           float(diff.max())))
    return numpy.array_equal(got, expected)


def still(out, rtcli):
    scene = setup(out, rtcli, 96, 54)
    layer = bpy.context.view_layer
    layer.use_pass_z = layer.use_pass_normal = True
    layer.rtcli.use_pass_albedo = True
    scene.render.filepath = os.path.join(out, 'still.exr')
    bpy.ops.render.render(write_still=True)
    got = blender_planes(os.path.join(out, 'still.exr'))
    want = hand_render(out, rtcli, 1, 96, 54)
    ok = all(same('Combined.' + c, got['Combined.' + c], want[c]) for c in 'RGB')
    ok = same('Combined.A', got['Combined.A'], numpy.ones_like(want['R'])) and ok
    ok = all(same('Albedo.' + c, got['Albedo.' + c], want['albedo.' + c]) for c in 'RGB') and ok
    ok = same('Normal.X', got['Normal.X'], want['normal.X']) and ok
    ok = same('Normal.Y', got['Normal.Y'], -want['normal.Z']) and ok  # glTF's -Z is Blender's +Y
    ok = same('Normal.Z', got['Normal.Z'], want['normal.Y']) and ok
    # Along the camera's axis: never longer than along the ray, equal at the centre, 1e10 for the world.
    depth, ray = got['Depth.Z'], want['depth.Z']
    hit = ray < 1e10
    ok = ok and bool(numpy.all(depth[~hit] == 1e10)) and bool(numpy.all(depth[hit] <= ray[hit]))
    ok = ok and bool(numpy.all(depth[hit] >= 0.75 * ray[hit])) and hit.sum() > 0.5 * hit.size
    print('addon: depth along the axis / along the ray: %.4f to %.4f over %d hits' %
          (float((depth[hit] / ray[hit]).min()), float((depth[hit] / ray[hit]).max()), int(hit.sum())))
    return ok


def animation(out, rtcli):
    scene = setup(out, rtcli, 64, 36)
    layer = bpy.context.view_layer
    layer.use_pass_z = False
    # A node rtcli cannot represent, to be named once for the whole animation.
    tree = bpy.data.materials['Red'].node_tree
    noise = tree.nodes.new('ShaderNodeTexNoise')
    tree.links.new(noise.outputs['Color'], tree.nodes['Principled BSDF'].inputs['Base Color'])
    scene.frame_start, scene.frame_end, scene.frame_step = 1, 5, 2
    scene.render.image_settings.file_format = 'OPEN_EXR'
    scene.render.filepath = os.path.join(out, 'anim_####')
    bpy.ops.render.render(animation=True)
    files = sorted(f for f in os.listdir(out) if f.startswith('anim_'))
    print('addon: animation wrote ' + ', '.join(files))
    ok = files == ['anim_0001.exr', 'anim_0003.exr', 'anim_0005.exr']
    frames = []
    for frame in (1, 3, 5):
        got = {k: v for k, v in read_exr(os.path.join(out, 'anim_%04d.exr' % frame))[2].items()}
        want = hand_render(out, rtcli, frame, 64, 36, aovs='')
        ok = all(same('frame %d %s' % (frame, c), got[c], want[c]) for c in 'RGB') and ok
        frames.append(got['R'])
    moved = not numpy.array_equal(frames[0], frames[1]) and not numpy.array_equal(frames[1], frames[2])
    print('addon: the box turns between frames: %s' % moved)
    return ok and moved


def error(out, rtcli):
    scene = setup(out, rtcli, 32, 18)
    broken = os.path.join(out, 'broken.hdr')
    with open(broken, 'wb') as f:
        f.write(b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 99999 +X 99999\n')  # far more pixels than bytes
    world = bpy.data.worlds.new('Sky')
    world.use_nodes = True
    environment = world.node_tree.nodes.new('ShaderNodeTexEnvironment')
    environment.image = bpy.data.images.load(broken, check_existing=False)
    world.node_tree.links.new(environment.outputs['Color'], world.node_tree.nodes['Background'].inputs['Color'])
    scene.world = world
    messages = []
    for executable in (rtcli, os.path.join(out, 'no-such-rtcli')):
        bpy.context.preferences.addons['rtcli'].preferences.executable = executable
        try:
            bpy.ops.render.render()
            messages.append('')
        except RuntimeError as e:  # the operator fails with the engine's error report
            messages.append(str(e))
        print('addon: report: ' + messages[-1].replace('\n', ' | '))
    return 'world.hdr' in messages[0] and 'rtcli not found at' in messages[1]


def display(linear):
    c = numpy.clip(linear, 0.0, 1.0)
    return numpy.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1.0 / 2.4) - 0.055)


def save_png(path, rgb):
    """Display values [3, rows top first, columns] as an 8-bit PNG, to look at."""
    _, height, width = rgb.shape
    pixels = numpy.round(numpy.clip(rgb, 0.0, 1.0) * 255.0).astype(numpy.uint8).transpose(1, 2, 0)
    rows = b''.join(b'\0' + pixels[y].tobytes() for y in range(height))

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))

    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)) +
                chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b''))


def cycles(out, rtcli):
    width, height, samples = 54, 96, 128
    scene = setup(out, rtcli, width, height)  # portrait: the sensor's width fits the image's height
    scene.unit_settings.scale_length = 0.01
    world = bpy.data.worlds.new('Sky')
    world.use_nodes = True
    world.node_tree.nodes['Background'].inputs['Color'].default_value = (0.2, 0.3, 0.5, 1.0)
    world.node_tree.nodes['Background'].inputs['Strength'].default_value = 0.5
    scene.world = world
    scene.view_settings.view_transform = 'Standard'
    scene.rtcli.samples = samples
    scene.render.image_settings.file_format = 'OPEN_EXR'
    scene.render.filepath = os.path.join(out, 'portrait_rtcli.exr')
    bpy.ops.render.render(write_still=True)
    scene.render.engine = 'CYCLES'  # as tools/cycles/fixture.py sets it up
    scene.cycles.device = 'CPU'
    scene.cycles.samples = samples
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.max_bounces = 12
    for key in ('diffuse_bounces', 'glossy_bounces', 'transmission_bounces', 'transparent_max_bounces'):
        setattr(scene.cycles, key, 12)
    scene.cycles.sample_clamp_direct = scene.cycles.sample_clamp_indirect = 0.0
    scene.cycles.pixel_filter_type = 'BOX'
    scene.cycles.filter_width = 1.0
    scene.render.threads_mode = 'FIXED'
    scene.render.threads = 2
    scene.render.filepath = os.path.join(out, 'portrait_cycles.exr')
    bpy.ops.render.render(write_still=True)
    ours = read_exr(os.path.join(out, 'portrait_rtcli.exr'))[2]
    theirs = read_exr(os.path.join(out, 'portrait_cycles.exr'))[2]
    a = numpy.stack([display(ours[c]) for c in 'RGB'])
    b = numpy.stack([display(theirs[c]) for c in 'RGB'])
    rmse = float(numpy.sqrt(numpy.mean((a - b) ** 2)))
    save_png(os.path.join(out, 'portrait_rtcli.png'), a)
    save_png(os.path.join(out, 'portrait_cycles.png'), b)
    # Framing: the floor's far edge meets the world on the same row in both images.
    print('addon: portrait %dx%d, %d samples, unit scale 0.01: RMSE of display values against Cycles %.4f' %
          (width, height, samples, rmse))
    return rmse < 0.05


def environment(out, rtcli):
    """A packed Environment Texture turned 30 degrees by a Mapping node, seen in two directions 90
    degrees apart: rtcli through the add-on against Cycles (a quarter turn wrong shows as another hue,
    rows written upside down as another brightness)."""
    scene = setup(out, rtcli, 48, 27)
    width, height = 128, 64
    u = (numpy.arange(width) + 0.5) / width
    v = (numpy.arange(height) + 0.5) / height
    sky = numpy.ones((height, width, 4), numpy.float32)
    sky[:, :, 0] = 0.5 + 0.5 * numpy.cos(2 * numpy.pi * u)[None, :]
    sky[:, :, 1] = 0.5 + 0.5 * numpy.sin(2 * numpy.pi * u)[None, :]
    sky[:, :, 2] = v[:, None]
    image = bpy.data.images.new('sky', width, height, float_buffer=True)
    image.pixels = sky.ravel()
    image.filepath_raw = os.path.join(out, 'sky.hdr')
    image.file_format = 'HDR'
    image.save()
    world = bpy.data.worlds.new('Sky')
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    texture = nodes.new('ShaderNodeTexEnvironment')
    texture.image = bpy.data.images.load(os.path.join(out, 'sky.hdr'))
    texture.image.pack()  # packed: the exporter writes it out itself, as a flat Radiance file
    mapping = nodes.new('ShaderNodeMapping')
    mapping.inputs['Rotation'].default_value[2] = math.radians(30)
    links.new(nodes.new('ShaderNodeTexCoord').outputs['Generated'], mapping.inputs['Vector'])
    links.new(mapping.outputs['Vector'], texture.inputs['Vector'])
    links.new(texture.outputs['Color'], nodes['Background'].inputs['Color'])
    scene.world = world
    scene.view_settings.view_transform = 'Standard'
    scene.cycles.samples = 16
    scene.cycles.use_denoising = False
    scene.render.image_settings.file_format = 'OPEN_EXR'
    camera = scene.camera
    camera.rotation_mode = 'XYZ'
    camera.location = (0, 0, 1)
    ok = True
    for turn in (0, 90):
        camera.rotation_euler = (math.radians(100), 0, math.radians(turn))  # just above the horizon
        images = []
        for engine in ('RTCLI', 'CYCLES'):
            scene.render.engine = engine
            scene.render.filepath = os.path.join(out, 'sky-%d-%s.exr' % (turn, engine.lower()))
            bpy.ops.render.render(write_still=True)
            planes = read_exr(scene.render.filepath)[2]
            images.append(numpy.stack([display(planes[c]) for c in 'RGB']))
            save_png(scene.render.filepath[:-4] + '.png', images[-1])
        rmse = float(numpy.sqrt(numpy.mean((images[0] - images[1]) ** 2)))
        print('addon: the world image turned 30 degrees, camera turned %d degrees: RMSE against Cycles %.4f' %
              (turn, rmse))
        ok = ok and rmse < 0.03
    return ok


def blend(out, rtcli):
    """The fixture with the engine chosen, saved as OUT/fixture.blend for ui_test.py."""
    scene = setup(out, rtcli, 640, 360)
    scene.rtcli.samples = 32
    scene.view_settings.view_transform = 'Filmic'
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out, 'fixture.blend'))
    # And exported by hand, for the tests to render with rtcli directly.
    load('blender_export', os.path.join(REPO, 'tools', 'blender_export.py')).export_with_warnings(
        os.path.join(out, 'hand', 'scene.glb'))
    return True


def heavy(out, rtcli):
    """A render far too long to finish, for cancel_test.py to stop with Blender's break (Ctrl-C, as Esc)."""
    scene = setup(out, rtcli, 320, 180)
    scene.rtcli.samples = 65535
    bpy.ops.render.render()
    print('addon heavy: the render returned')
    return True


CASES = {'still': still, 'animation': animation, 'error': error, 'cycles': cycles, 'environment': environment,
         'blend': blend, 'heavy': heavy}

if __name__ == '__main__':
    argv = sys.argv[sys.argv.index('--') + 1:]
    case, out, rtcli = argv[0], os.path.abspath(argv[1]), os.path.abspath(argv[2])
    os.makedirs(out, exist_ok=True)
    if not CASES[case](out, rtcli):
        sys.exit('addon %s: FAILED' % case)
    print('addon %s: ok' % case)
