# The add-on's settings: per scene (saved in the .blend, as Cycles' are), per view layer (the
# Albedo pass; Depth and Normal are Blender's own pass toggles), and the rtcli executable in the
# add-on's preferences (it belongs to the machine, not to the file).
#
# Licence: Apache-2.0, as the rest of rtcli.
import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty, StringProperty


class RtcliPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    executable: StringProperty(
        name='rtcli executable', subtype='FILE_PATH', default='',
        description='The rtcli program to run (empty: the one found on PATH)')

    def draw(self, context):
        self.layout.prop(self, 'executable')


class RtcliSceneSettings(bpy.types.PropertyGroup):
    integrator: EnumProperty(
        name='Integrator', default='path',
        items=[('path', 'Path Tracing', 'Global illumination, as Cycles: the world and every surface light the scene'),
               ('whitted', 'Whitted', 'Ray tracing with reflections, refractions and soft shadows; the world is '
                                      'seen but lights nothing')])
    samples: IntProperty(name='Samples', default=64, min=1, max=65535,
                         description='Path tracing: the most samples per pixel (--spp)')
    noise_threshold: FloatProperty(name='Noise Threshold', default=0.0, min=0.0, max=1.0, precision=4,
                                   description='Path tracing: a pixel stops once its relative error is below this '
                                               '(0: off, every pixel takes all its samples)')
    max_depth: IntProperty(name='Max Bounces', default=12, min=0, max=64,
                           description='Bounces after the camera ray (--max-depth); Cycles\' default is 12')
    denoise: BoolProperty(name='Denoise', default=False,
                          description='Path tracing: rtcli\'s denoiser, guided by albedo, normal and depth')
    seed: IntProperty(name='Seed', default=0, min=0, description='Seed of every random stream')
    aa: EnumProperty(name='Anti-aliasing', default='adaptive',
                     items=[('adaptive', 'Adaptive', 'Cells split where their samples differ'),
                            ('uniform', 'Uniform', 'The same rays in every pixel'),
                            ('none', 'None', 'One ray through each pixel\'s centre')])
    shadow_samples: IntProperty(name='Shadow Samples', default=16, min=1, max=1024,
                                description='Whitted: shadow rays per area light and shading point')
    glossy_samples: IntProperty(name='Glossy Samples', default=8, min=1, max=256,
                                description='Whitted: rays per glossy reflection')
    keep_files: BoolProperty(name='Keep Export', default=False,
                             description='Keep each frame\'s export, command and EXR in the temporary folder (its '
                                         'path is reported), to run rtcli on it by hand')


class RtcliViewLayerSettings(bpy.types.PropertyGroup):
    use_pass_albedo: BoolProperty(name='Albedo', default=False,
                                  description='The first hit\'s diffuse colour, as the denoiser sees it')


CLASSES = (RtcliPreferences, RtcliSceneSettings, RtcliViewLayerSettings)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.rtcli = PointerProperty(type=RtcliSceneSettings)
    bpy.types.ViewLayer.rtcli = PointerProperty(type=RtcliViewLayerSettings)


def unregister():
    del bpy.types.ViewLayer.rtcli
    del bpy.types.Scene.rtcli
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
