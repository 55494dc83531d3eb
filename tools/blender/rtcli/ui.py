# The panels: rtcli's settings in Render Properties, its passes in View Layer Properties, and
# Blender's own panels (output, colour management, lights, cameras) opened to the engine.
#
# Licence: Apache-2.0, as the rest of rtcli.
import bpy

from . import locate

ENGINE = 'RTCLI'
# Blender's panels that apply to any engine that renders what the glTF export carries.
SHARED_PANELS = {
    'DATA_PT_EEVEE_light', 'DATA_PT_EEVEE_light_distance', 'DATA_PT_lens', 'DATA_PT_camera', 'DATA_PT_camera_dof',
    'DATA_PT_camera_dof_aperture', 'EEVEE_MATERIAL_PT_surface', 'EEVEE_MATERIAL_PT_context_material',
    'EEVEE_WORLD_PT_surface', 'RENDER_PT_color_management', 'RENDER_PT_color_management_curves',
}


class RtcliPanel:
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    COMPAT_ENGINES = {ENGINE}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES


class RENDER_PT_rtcli(RtcliPanel, bpy.types.Panel):
    bl_label = 'rtcli'
    bl_context = 'render'

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        settings = context.scene.rtcli
        layout.prop(settings, 'integrator')
        if settings.integrator == 'path':
            layout.prop(settings, 'samples')
            layout.prop(settings, 'noise_threshold')
            layout.prop(settings, 'denoise')
        else:
            layout.prop(settings, 'aa')
            layout.prop(settings, 'shadow_samples')
            layout.prop(settings, 'glossy_samples')
        layout.prop(settings, 'max_depth')
        layout.prop(settings, 'seed')
        # Tone map and exposure are the scene's view transform: rtcli's result is linear and
        # Blender shows and saves it through them, as it does Cycles' (Color Management).
        view = context.scene.view_settings
        layout.prop(view, 'view_transform', text='Tone Map')
        layout.prop(view, 'look')
        layout.prop(view, 'exposure')
        render = context.scene.render
        layout.prop(render, 'threads_mode')
        row = layout.row()
        row.enabled = render.threads_mode == 'FIXED'
        row.prop(render, 'threads')
        preferences = locate.preferences(context)
        if preferences is not None:
            layout.prop(preferences, 'executable')
        found, message = locate.executable(context)
        if not found:
            layout.label(text=message, icon='ERROR')
        layout.prop(settings, 'keep_files')


class VIEWLAYER_PT_rtcli_passes(RtcliPanel, bpy.types.Panel):
    bl_label = 'Passes'
    bl_context = 'view_layer'

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        view_layer = context.view_layer
        layout.prop(view_layer, 'use_pass_combined')
        layout.prop(view_layer, 'use_pass_z', text='Depth')
        layout.prop(view_layer, 'use_pass_normal', text='Normal')
        layout.prop(view_layer.rtcli, 'use_pass_albedo')


CLASSES = (RENDER_PT_rtcli, VIEWLAYER_PT_rtcli_passes)


def _shared_panels():
    for panel in bpy.types.Panel.__subclasses__():
        engines = getattr(panel, 'COMPAT_ENGINES', None)
        if engines is None or panel.__name__ in ('VIEWLAYER_PT_layer_passes', 'VIEWLAYER_PT_filter'):
            continue
        if 'BLENDER_RENDER' in engines or panel.__name__ in SHARED_PANELS:
            yield panel


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    for panel in _shared_panels():
        panel.COMPAT_ENGINES.add(ENGINE)


def unregister():
    for panel in _shared_panels():
        panel.COMPAT_ENGINES.discard(ENGINE)
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
