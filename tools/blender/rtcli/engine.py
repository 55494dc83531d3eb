# The render engine "rtcli": each frame Blender asks for (F12, Ctrl-F12, -f, -a) is exported with
# the one exporter (export.py) into a temporary folder, rendered there by the rtcli program as a
# float EXR with the passes the view layer asks for, and loaded into Blender's render result.
# Progress comes from rtcli's progress lines; Esc (or Blender's break in background mode) ends the
# rtcli process; rtcli's errors and warnings go to Blender's report.
#
# Licence: Apache-2.0, as the rest of rtcli.
import os
import shlex
import shutil
import tempfile
import threading

import bpy

from . import export, locate, material_check, process, result
from .command import RenderRequest, render_arguments


def on_main_thread(task):
    """task() on Blender's main thread: an F12 render runs in a job thread, where operators such as
    the glTF export must not run; the main thread's event loop picks it up from a timer."""
    if threading.current_thread() is threading.main_thread():
        return task()
    done = threading.Event()
    box = {}

    def run():
        try:
            box['value'] = task()
        except BaseException as e:  # noqa: B902 - given back to the render thread
            box['error'] = e
        done.set()
        return None

    bpy.app.timers.register(run, first_interval=0.0)
    done.wait()  # not cancellable: an export always ends by giving the user's data back
    if 'error' in box:
        raise box['error']
    return box['value']


def image_size(render):
    scale = render.resolution_percentage
    return max(1, render.resolution_x * scale // 100), max(1, render.resolution_y * scale // 100)


class RtcliRenderEngine(bpy.types.RenderEngine):
    bl_idname = 'RTCLI'
    bl_label = 'rtcli'
    bl_use_preview = False
    bl_use_postprocess = True
    bl_use_shading_nodes_custom = False  # the standard shader nodes, which the glTF export reads
    bl_use_eevee_viewport = True  # the viewport's Material Preview and Rendered modes show EEVEE

    def update_render_passes(self, scene=None, renderlayer=None):
        self.register_pass(scene, renderlayer, 'Combined', 4, 'RGBA', 'COLOR')
        if renderlayer.use_pass_z:
            self.register_pass(scene, renderlayer, 'Depth', 1, 'Z', 'VALUE')
        if renderlayer.use_pass_normal:
            self.register_pass(scene, renderlayer, 'Normal', 3, 'XYZ', 'VECTOR')
        if renderlayer.rtcli.use_pass_albedo:
            self.register_pass(scene, renderlayer, 'Albedo', 3, 'RGB', 'COLOR')

    def fail(self, message):
        self.report({'ERROR'}, message)
        self.error_set(message)

    def render(self, depsgraph):
        scene = depsgraph.scene
        view_layer = depsgraph.view_layer
        executable, why = locate.executable(bpy.context)
        if executable is None:
            return self.fail(why)
        if scene.camera is None:
            return self.fail('rtcli: the scene has no camera to render from')
        keep = scene.rtcli.keep_files
        folder = tempfile.mkdtemp(prefix='rtcli-')
        try:
            kept = self.render_in(folder, scene, view_layer, executable)
        finally:
            if not (keep or kept):
                shutil.rmtree(folder, ignore_errors=True)

    def first_of_job(self, scene):
        """Warnings about the scene are given once: for a still, or the first frame of an animation."""
        return not self.is_animation or scene.frame_current == scene.frame_start

    def render_in(self, folder, scene, view_layer, executable):
        """Renders into `folder`; True if the folder is to be kept (rtcli failed: its input is evidence)."""
        settings = scene.rtcli
        glb = os.path.join(folder, 'scene.glb')
        exr = os.path.join(folder, 'frame.exr')
        self.update_stats('', 'rtcli: exporting the scene')
        original = scene.original  # the user's scene, not the render's evaluated copy
        layer = original.view_layers.get(view_layer.name) or original.view_layers[0]

        def export_scene():
            # `blender -b -f` renders with no window in the context, so no view layer or active
            # object either; the glTF exporter reads all three.
            context = {'scene': original, 'view_layer': layer, 'active_object': layer.objects.active,
                       'object': layer.objects.active,
                       'selected_objects': [o for o in layer.objects if o.select_get(view_layer=layer)]}
            windows = bpy.context.window_manager.windows
            if bpy.context.window is None and len(windows) > 0:
                context['window'] = windows[0]
            with bpy.context.temp_override(**context):
                return export.export_for_rtcli(glb)

        try:
            export_warnings = on_main_thread(export_scene)
        except Exception as e:  # the exporter's own failure, with its message (nothing to keep)
            self.fail('rtcli: the glTF export failed: %s' % e)
            return False
        if self.first_of_job(scene):
            for warning in export_warnings + material_check.warnings_for(bpy.data.materials):
                self.report({'WARNING'}, 'rtcli: ' + warning)
            if scene.render.film_transparent:
                self.report({'WARNING'}, 'rtcli: Film > Transparent is not carried over: the world is rendered')
        width, height = image_size(scene.render)
        aovs = [name for name, wanted in (('albedo', view_layer.rtcli.use_pass_albedo),
                                          ('normal', view_layer.use_pass_normal),
                                          ('depth', view_layer.use_pass_z)) if wanted]
        request = RenderRequest(
            glb, exr, scene.frame_current, scene.render.fps / scene.render.fps_base, width, height,
            camera=scene.camera.name, integrator=settings.integrator, samples=settings.samples,
            noise_threshold=settings.noise_threshold, max_depth=settings.max_depth,
            denoise=settings.denoise, seed=settings.seed,
            threads=scene.render.threads if scene.render.threads_mode == 'FIXED' else 0, aa=settings.aa,
            shadow_samples=settings.shadow_samples, glossy_samples=settings.glossy_samples, aovs=aovs)
        argv = [executable] + render_arguments(request)
        with open(os.path.join(folder, 'command.sh'), 'w') as f:  # to run it again by hand
            f.write(' '.join(shlex.quote(a) for a in argv) + '\n')
        self.update_stats('', 'rtcli: rendering frame %d' % scene.frame_current)

        def progress(fraction):
            self.update_progress(fraction)
            self.update_stats('', 'rtcli: frame %d, %d%%' % (scene.frame_current, round(100 * fraction)))

        outcome = process.run(argv, folder, progress, self.test_break)
        if outcome.cancelled:
            return False
        where = folder + os.sep
        for line in outcome.warnings()[:20]:
            self.report({'WARNING'}, line.replace(where, ''))
        if outcome.code != 0:
            errors = outcome.errors() or outcome.lines[-5:] or ['rtcli exited with status %s' % outcome.code]
            for message in errors[:10]:
                self.report({'ERROR'}, message.replace(where, ''))
            self.error_set('%s (the export and command are kept in %s)' % (errors[0].replace(where, ''), folder))
            return True
        camera = result.gltf_camera(glb, scene.camera.name)
        w, h, passes = result.load_passes(exr, camera)
        render_result = self.begin_result(0, 0, w, h, layer=view_layer.name)
        layer = render_result.layers[0]
        for render_pass in layer.passes:
            values = passes.get(render_pass.name)
            if values is not None and values.shape[1] == render_pass.channels:
                render_pass.rect = values
        self.end_result(render_result)
        if settings.keep_files:
            self.report({'INFO'}, 'rtcli: frame %d kept in %s' % (scene.frame_current, folder))
        return False


def register():
    bpy.utils.register_class(RtcliRenderEngine)


def unregister():
    bpy.utils.unregister_class(RtcliRenderEngine)
